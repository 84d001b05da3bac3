// ReciprocalSqrt: reciprocal square root for the shading unit's normalisers, the way 1990s
// shading hardware did it — a seed ROM and one Newton-Raphson step — instead of a
// digit-recurrence square root followed by a divider (HwConfig::shading_normalizer =
// "newton", the default; "recurrence" keeps the SqrtExtractor + divider datapath).
//
// Input L > 0 (an integer). The unit normalises L by an even shift 2k to the mantissa
// m = L · 2^-2k in [2^(2P), 2^(2P+2)) (P = kPrecision; right shifts truncate), looks up
// y0 ≈ 2^(2P+1) / sqrt(m) in a ROM indexed by the top kSeedBits bits of m (the value for
// the middle of the cell, 0.75 · 2^kSeedBits entries of P + 1 bits), then
//     y1 = y0 · (3 · 2^(4P+2) − m · y0²) / 2^(4P+3)        (truncated),
// so that 1/sqrt(L) ≈ y1 · 2^-(2P+1+k). The seed's relative error is below 2^-(kSeedBits+1)
// (half a ROM cell), the Newton step squares it (≈ 1.5 · 2^-22) and the final truncation
// adds up to 2^-P: under 2^-18 in all, checked exhaustively below 2^20 and on random
// inputs up to 2^120 by the tests, far below the 1.unit_frac_bits format it feeds.
#pragma once
#include <cstdint>

namespace qacc {

class ReciprocalSqrt {
 public:
  static constexpr int kPrecision = 20;  // P: y has P + 1 bits
  static constexpr int kSeedBits = 10;   // ROM index width
  struct Result {
    std::int64_t y = 0;  // ≈ 2^(2P+1) / sqrt(m)
    int k = 0;           // L = m · 2^2k
  };
  // L must be positive and below 2^126.
  static Result compute(unsigned __int128 L);
  static int romEntries() { return (1 << kSeedBits) - (1 << (kSeedBits - 2)); }
  static int romBits() { return romEntries() * (kPrecision + 1); }
};

}  // namespace qacc
