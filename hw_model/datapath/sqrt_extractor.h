// SqrtExtractor: the square-root extractor of the depth unit (IMOGENE, digest §1).
//
// Hardware: a non-restoring digit recurrence producing log2(radix) result bits per step,
// pipelined (one operand per cycle); its latency, one cycle per digit step plus one, is
// the pixel pipeline unit's (timing/pixel_pipeline_unit.h).
// Its result is, bit for bit, floor(sqrt(n)) for an unsigned integer n: `recurrence`
// models the hardware algorithm digit by digit; `compute` returns the same bits faster
// (double-precision estimate + exact integer correction). Tests check they agree.
#pragma once
#include <cmath>
#include <cstdint>

#include "hw_model/datapath/fixed_point.h"

namespace qacc {

class SqrtExtractor {
 public:
  // The operand the extractor reads from a `width`-bit Δ register holding `reg`: its bits
  // as an unsigned number. A Δ that was not negative but wrapped in the register (overflow
  // "wrap") has its sign bit set: the extractor reads 2^width + reg, as the digit recurrence
  // over those bits would, instead of a 128-bit number no square root fits in (whose
  // correction loop never ended). Unchanged for every value that fits.
  static unsigned __int128 operand(i128 reg, int width) {
    return (unsigned __int128)reg & ((((unsigned __int128)1) << width) - 1);
  }
  // Digit recurrence with radix 2 or 4 over an operand of `inputBits` bits (even-rounded up).
  static std::uint64_t recurrence(unsigned __int128 n, int inputBits, int radix);
  // Same result, fast path: the host's double square root, corrected to the exact floor
  // (inline for a 64-bit operand, the common case: every covered pixel takes one).
  static std::uint64_t compute(unsigned __int128 n) {
    if (n >> 64) return computeWide(n);
    const std::uint64_t m = std::uint64_t(n);
    if (m == 0) return 0;
    std::uint64_t x = std::uint64_t(std::sqrt(double(m)));
    // x <= 2^32 - 1, so x² fits 64 bits; (x + 1)² does too unless x = 2^32 - 1, where it is
    // 2^64 > m and the root is x.
    if (x > 0xFFFFFFFFull) x = 0xFFFFFFFFull;
    while (x * x > m) --x;
    while (x < 0xFFFFFFFFull && (x + 1) * (x + 1) <= m) ++x;
    return x;
  }

 private:
  static std::uint64_t computeWide(unsigned __int128 n);  // n >= 2^64
};

}  // namespace qacc
