// SqrtExtractor: the square-root extractor of the depth unit (IMOGENE, digest §1).
//
// Hardware: a non-restoring digit recurrence producing log2(radix) result bits per step,
// pipelined (one operand per cycle); its latency, one cycle per digit step plus one, is
// the pixel pipeline unit's (timing/pixel_pipeline_unit.h).
// Its result is, bit for bit, floor(sqrt(n)) for an unsigned integer n: `recurrence`
// models the hardware algorithm digit by digit; `compute` returns the same bits faster
// (double-precision estimate + exact integer correction). Tests check they agree.
#pragma once
#include <cstdint>

#include "hw_model/datapath/fixed_point.h"

namespace qacc {

class SqrtExtractor {
 public:
  // Digit recurrence with radix 2 or 4 over an operand of `inputBits` bits (even-rounded up).
  static std::uint64_t recurrence(unsigned __int128 n, int inputBits, int radix);
  // Same result, fast path.
  static std::uint64_t compute(unsigned __int128 n);
};

}  // namespace qacc
