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
#include <array>
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
  // L must be positive and below 2^126. Inline: the shading unit calls it four times a pixel.
  static Result compute(unsigned __int128 L) {
    constexpr int P = kPrecision, S = kSeedBits;
    Result r;
    if (L == 0) return r;
    // Even shift s = 2k bringing the bit length of m to 2P+1 or 2P+2.
    const std::uint64_t hi = std::uint64_t(L >> 64);
    const int len = hi ? 128 - __builtin_clzll(hi) : 64 - __builtin_clzll(std::uint64_t(L));
    int s = len - (2 * P + 2);
    if (s & 1) ++s;
    const std::uint64_t m = std::uint64_t(s >= 0 ? (L >> s) : (L << -s));
    r.k = s / 2;
    const std::int64_t y0 = kSeedRom[std::size_t(m >> (2 * P + 2 - S))];
    const unsigned __int128 three = (unsigned __int128)3 << (4 * P + 2);
    const unsigned __int128 my2 = (unsigned __int128)m * (unsigned __int128)(y0 * y0);
    const unsigned __int128 t = three - my2;  // > 0: m y0² is within a few % of 2^(4P+2)
    r.y = std::int64_t(((unsigned __int128)y0 * t) >> (4 * P + 3));
    return r;
  }
  static int romEntries() { return (1 << kSeedBits) - (1 << (kSeedBits - 2)); }
  static int romBits() { return romEntries() * (kPrecision + 1); }
  // The seed ROM: entry i (i in [2^(S-2), 2^S)) covers m in [i, i+1) · 2^(2P+2-S). Built
  // when the program starts (no static initialiser of another file reads it).
  static const std::array<std::int64_t, (1 << kSeedBits)> kSeedRom;
};

}  // namespace qacc
