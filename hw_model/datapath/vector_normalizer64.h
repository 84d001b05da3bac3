// VectorNormalizer64: the shading unit's vector normaliser (shading_arithmetic.h) in 64-bit
// host registers — the same bits as normalizeT, the 128-bit reference in
// shading_arithmetic.cpp (tests compare the two datapaths). A vector is brought to
// normal_bits by the leading-zero shift, then scaled by its reciprocal length: seed ROM +
// Newton step (ReciprocalSqrt::compute64), or, with shading_normalizer = "recurrence", the
// square root and the divider (normal_bits <= 23 only: len2 · 2^16 must stay below 2^63).
//
// Why 64 bits hold every register (nb = normal_bits <= 30, uf = unit_frac_bits <=
// min(nb, kMaxUnitFracBits = 20), P = ReciprocalSqrt::kPrecision = 20):
//  - after the shift the longest component has nb - 1 bits, which rounding carries to 2^(nb-1)
//    at most, and at least nb - 2 bits: 2^(nb-2) <= max |n_k| <= 2^(nb-1), so
//    len2 = Σ n_k² < 3 · 2^(2nb-2) <= 3 · 2^58 (a 64-bit input of compute64) and len2 > 0;
//  - Newton: y <= 2^(P+1) (the Newton step for 1/sqrt never overshoots: y1 <= 2^(2P+1) /
//    sqrt(m), m >= 2^(2P)), so |n_k y| <= 2^(nb+P) <= 2^50; the shift sh = k + 2P + 1 - uf
//    is at least 1 (L >= 1 gives k >= -P, and uf <= P) and at most 44 (len2 < 2^60 gives
//    k <= 9, and uf >= 6), so |n_k y| + 2^(sh-1) < 2^63;
//  - recurrence (nb <= 23): len2 · 2^2G < 3 · 2^60 (isqrt63's domain); the root is at least
//    max |n_k| · 2^G >= 2^(nb-2+G), so rs = 2^(uf+G+nb-1) / root <= 2^(uf+1) + 1 and
//    |n_k rs| < 2^(nb+uf+1) <= 2^44.
// So no rounding shift below can overflow (shiftRoundFitR), and none has a shift below 1.
#pragma once
#include <cmath>
#include <cstdint>

#include "hw_model/config/hw_config.h"
#include "hw_model/datapath/fixed_point.h"
#include "hw_model/datapath/reciprocal_sqrt.h"

namespace qacc {

static_assert(kMaxUnitFracBits <= ReciprocalSqrt::kPrecision,
              "the Newton normaliser's final shift k + 2P + 1 - unit_frac_bits must stay >= 1");

// floor(sqrt(x)) for 0 <= x < 2^63: the double estimate is off by at most one.
inline std::int64_t isqrt63(std::int64_t x) {
  std::int64_t q = std::int64_t(std::sqrt(double(x)));
  if (q * q > x) --q;
  else if ((q + 1) * (q + 1) <= x) ++q;
  return q;
}

template <Rounding R, Normalizer Z>
class VectorNormalizer64 {
 public:
  static constexpr int kGuard = 8;  // G: guard bits of the recurrence's root
  explicit VectorNormalizer64(const HwConfig& cfg) : nb_(cfg.normal_bits), uf_(cfg.unit_frac_bits) {}

  // A vector of exact 128-bit components (a shading field at a pixel, a cap's normal).
  [[gnu::always_inline]] inline void normalize(const i128 in[3], std::int64_t out[3]) const {
    const unsigned __int128 m = magnitude(in[0]) | magnitude(in[1]) | magnitude(in[2]);
    if (m == 0) {
      out[0] = out[1] = out[2] = 0;
      return;
    }
    const int len = bitLength(m);
    const int shift = len - (nb_ - 1);
    std::int64_t n[3];
    if (shift <= 0) {
      for (int k = 0; k < 3; ++k) n[k] = std::int64_t(in[k]) * (std::int64_t(1) << -shift);
    } else if (len <= 62) {
      // |in_k| < 2^62: the rounding cannot overflow.
      for (int k = 0; k < 3; ++k) n[k] = shiftRoundFitR<R, std::int64_t>(std::int64_t(in[k]), shift);
    } else if constexpr (R != Rounding::NearestEven) {
      // floor((v + 2^(s-1)) / 2^s) = floor((floor(v / 2^(s-1)) + 1) / 2): only v >> (s-1),
      // which has nb bits, comes down to 64 bits.
      for (int k = 0; k < 3; ++k) {
        const std::int64_t t = std::int64_t(in[k] >> (shift - 1));
        n[k] = R == Rounding::Truncate ? t >> 1 : (t + 1) >> 1;
      }
    } else {
      for (int k = 0; k < 3; ++k) n[k] = std::int64_t(shiftRoundR<R, i128>(in[k], shift));
    }
    scale(n, out);
  }

  // A vector of 64-bit components below 2^62 in magnitude (the half vector L + V of two
  // vectors of 1.unit_frac: below 2^(uf+2)).
  [[gnu::always_inline]] inline void normalize(const std::int64_t in[3], std::int64_t out[3]) const {
    const std::uint64_t m = magnitude64(in[0]) | magnitude64(in[1]) | magnitude64(in[2]);
    if (m == 0) {
      out[0] = out[1] = out[2] = 0;
      return;
    }
    const int len = 64 - __builtin_clzll(m);
    const int shift = len - (nb_ - 1);
    std::int64_t n[3];
    if (shift <= 0) {
      for (int k = 0; k < 3; ++k) n[k] = in[k] * (std::int64_t(1) << -shift);
    } else {
      for (int k = 0; k < 3; ++k) n[k] = shiftRoundFitR<R, std::int64_t>(in[k], shift);
    }
    scale(n, out);
  }

 private:
  static std::uint64_t magnitude64(std::int64_t v) { return v < 0 ? std::uint64_t(0) - std::uint64_t(v) : std::uint64_t(v); }

  // n (the shifted vector, 2^(nb-2) <= max |n_k| <= 2^(nb-1)) → the unit vector in 1.uf.
  [[gnu::always_inline]] inline void scale(const std::int64_t n[3], std::int64_t out[3]) const {
    const std::int64_t len2 = n[0] * n[0] + n[1] * n[1] + n[2] * n[2];
    if constexpr (Z == Normalizer::Newton) {
      // unit = n / sqrt(len2) in 1.uf, with 1/sqrt(len2) = y · 2^-(2P+1+k).
      const ReciprocalSqrt::Result r = ReciprocalSqrt::compute64(std::uint64_t(len2));
      const int sh = r.k + 2 * ReciprocalSqrt::kPrecision + 1 - uf_;
      for (int k = 0; k < 3; ++k) out[k] = shiftRoundFitR<R, std::int64_t>(n[k] * r.y, sh);
    } else {
      // R = 2^(uf + G + nb - 1) / sqrt(len2 · 2^2G), then unit = n R >> (nb - 1).
      const std::int64_t root = isqrt63(len2 * (std::int64_t(1) << (2 * kGuard)));
      if (root == 0) {
        out[0] = out[1] = out[2] = 0;
        return;
      }
      const std::int64_t rs = std::int64_t(divRound(i128(1) << (uf_ + kGuard + nb_ - 1), root, R));
      for (int k = 0; k < 3; ++k) out[k] = shiftRoundFitR<R, std::int64_t>(n[k] * rs, nb_ - 1);
    }
  }

  int nb_, uf_;
};

}  // namespace qacc
