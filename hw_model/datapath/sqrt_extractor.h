// SqrtUnit: the square-root extractor of the depth unit (IMOGENE, digest §1).
//
// Hardware: a non-restoring digit recurrence producing log2(radix) result bits per step,
// pipelined (one operand per cycle), latency = ceil(resultBits / log2(radix)) + 1 cycles.
// Its result is, bit for bit, floor(sqrt(n)) for an unsigned integer n: `recurrence`
// models the hardware algorithm digit by digit; `compute` returns the same bits faster
// (double-precision estimate + exact integer correction). Tests check they agree.
#pragma once
#include <cstdint>

#include "hw_model/datapath/fixed_point.h"

namespace qacc {

class SqrtUnit {
 public:
  // Digit recurrence with radix 2 or 4 over an operand of `inputBits` bits (even-rounded up).
  static std::uint64_t recurrence(unsigned __int128 n, int inputBits, int radix);
  // Same result, fast path.
  static std::uint64_t compute(unsigned __int128 n);
  // Pipeline latency in cycles for an operand of `inputBits` bits.
  static int latency(int inputBits, int radix);
};

}  // namespace qacc
