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

#include "hw_model/datapath/fixed_point.h"

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
    int s = bitLength(L) - (2 * P + 2);
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
  // The same Result as compute(L) for L below 2^64, in fewer host instructions (the shading
  // datapath with 64-bit registers, vector_normalizer64.h, calls it four times a pixel):
  //  - the even shift: with c = clz(L), the bit length is 64 - c and s = 2k = 64 - c - (2P+2)
  //    rounded up to even = 64 - (2P+2) - c + (c & 1); so m = L · 2^-s is L shifted fully
  //    left (no bit lost), then right by 64 - (2P+2) + (c & 1), which truncates exactly where
  //    L >> s does;
  //  - the Newton step is the same integer, rewritten: y0 · (3 · 2^(4P+2) − m y0²) =
  //    3 y0 · 2^(4P+2) − m · y0³, where y0 < 2^(P+1) makes y0³ < 2^(3P+3) = 2^63 a 64-bit
  //    value, so m · y0³ is one 64 x 64 → 128-bit multiply (m < 2^(2P+2)). The numerator is
  //    positive (t > 0 above) and 3 y0 · 2^(4P+2) is a multiple of 2^64, so its bits above
  //    2^64 are 3 y0 · 2^(4P+2-64) − (m y0³ >> 64) − (a borrow when the low half of m y0³ is
  //    not 0), and the shift by 4P+3 >= 64 keeps only those.
  // Tests check it against compute().
  static Result compute64(std::uint64_t L) {
    constexpr int P = kPrecision, S = kSeedBits, W = 64 - (2 * P + 2);
    static_assert(W > 0 && W % 2 == 0 && 3 * P + 3 <= 63 && 4 * P + 3 >= 64, "m and y0^3 must fit 64 bits, the shift must drop the low half");
    Result r;
    if (L == 0) return r;
    const int c = __builtin_clzll(L);
    const std::uint64_t m = (L << c) >> (W + (c & 1));
    r.k = W / 2 - (c >> 1);  // (W - c + (c & 1)) / 2, W even
    const std::uint64_t y0 = std::uint64_t(kSeedRom[std::size_t(m >> (2 * P + 2 - S))]);
    const unsigned __int128 my3 = (unsigned __int128)m * (y0 * y0 * y0);
    const std::uint64_t hi = ((3 * y0) << (4 * P + 2 - 64)) - std::uint64_t(my3 >> 64) - (std::uint64_t(my3) != 0);
    r.y = std::int64_t(hi >> (4 * P + 3 - 64));
    return r;
  }
  static int romEntries() { return (1 << kSeedBits) - (1 << (kSeedBits - 2)); }
  static int romBits() { return romEntries() * (kPrecision + 1); }
  // The seed ROM: entry i (i in [2^(S-2), 2^S)) covers m in [i, i+1) · 2^(2P+2-S). Built
  // when the program starts (no static initialiser of another file reads it).
  static const std::array<std::int64_t, (1 << kSeedBits)> kSeedRom;
};

}  // namespace qacc
