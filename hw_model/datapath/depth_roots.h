// Depth roots: the depths of the quadric on the line of a pixel, from a (constant), the
// interpolated b and c, and s = sqrt(Δ) from the square-root extractor, all at the primitive's block
// scale 2^e; depths come out in the internal depth format (depth_frac_bits fraction bits,
// depth_bits wide; values beyond its range are clamped and counted — they lie outside
// the view volume 0 <= z <= 1 anyway). Two variants (HwConfig::depth_variant):
//  - Stable (divider): q = −(b + sign(b) s), z1 = q / a, z2 = c / q. No cancellation;
//    a = 0 gives the single root c / q = −c / 2b (paraboloid seen along its axis).
//  - Reciprocal (one multiplier, no divider): z = (−b ∓ s) · (1/a) with 1/a a setup
//    constant. Cheaper; loses bits to cancellation when b² ≫ |ac|, and a primitive whose
//    a quantises to 0 has no reciprocal: it is not drawn (counted by the engines).
#pragma once
#include <cstdint>
#include <utility>

#include "hw_model/config/hw_config.h"
#include "hw_model/datapath/overflow_counters.h"
#include "hw_model/datapath/primitive_setup.h"

namespace qacc {

struct DepthRoots {
  int count = 0;
  // Ascending, in the depth format: depth_bits <= 40 (HwConfig), so a 64-bit register holds
  // every value (and the host keeps the pair in registers).
  std::int64_t z[2] = {0, 0};
};

// The roots of the primitive on the line of a pixel (ascending), in the depth format.
DepthRoots depthRoots(const PrimitiveSetup& s, const HwConfig& cfg, i128 b, i128 c, i128 sq, OverflowCounters& ovf);

// Narrows a depth to the depth datapath (clamped, counted as a depth clamp).
inline i128 clampDepth(i128 z, const HwConfig& cfg, OverflowCounters& ovf) {
  const i128 hi = (i128(1) << (cfg.depth_bits - 1)) - 1, lo = -hi - 1;
  if (z > hi) {
    ++ovf.depth_clamps;
    return hi;
  }
  if (z < lo) {
    ++ovf.depth_clamps;
    return lo;
  }
  return z;
}

// depthRoots for the rounding mode R and variant V of the configuration (cfg.rounding ==
// R, cfg.depth_variant == V): the pixel datapath's inner loop is instantiated per mode.
// T is the register type of b, c, s and the depths: i128 in general; std::int64_t where the
// widths fit it (the same values, cheaper on the host), which the caller guarantees:
//   |b|, |c|, |s| <= 2^value_bits, so |q| < 2^(value_bits+1), and the dividends q · 2^Fz
//   and c · 2^Fz stay below 2^62 (divRound64's domain) when value_bits + 1 + Fz <= 62; a
//   is a value_bits register; 0 <= z0 <= 2^Fz and zShift <= Fz / 2 (setup); the clamped
//   depths are depth_bits <= 40 wide. The reciprocal variant's product (-b ∓ s) · recipM,
//   up to value_bits + recip_bits + 1 <= 89 bits, is taken in i128 from 64-bit factors.
// invAbsA = 1.0 / |a| (a != 0), for T = std::int64_t: the stable variant's q / a, a constant
// divisor, then costs the host a multiplication (divRound64ByReciprocal, the same quotient).
template <Rounding R, DepthVariant V, typename T = i128>
inline DepthRoots depthRootsT(const PrimitiveSetup& s, const HwConfig& cfg, T b, T c, T sq, OverflowCounters& ovf,
                              double invAbsA = 0) {
  // A root t (depth format, t units) as window depth z = z0 + t 2^-zShift.
  const T hi = (T(1) << (cfg.depth_bits - 1)) - 1, lo = -hi - 1;
  const auto windowDepth = [&](auto t) {  // t: T, or i128 for the reciprocal variant's product
    T tc;                                 // clampDepth(t, cfg, ovf)
    if (t > hi) {
      ++ovf.depth_clamps;
      tc = hi;
    } else if (t < lo) {
      ++ovf.depth_clamps;
      tc = lo;
    } else {
      tc = T(t);
    }
    const T z = T(s.z0) + shiftRoundR<R>(tc, s.zShift);
    return std::int64_t(z > hi ? hi : (z < lo ? lo : z));
  };
  DepthRoots r;
  const int Fz = cfg.depth_frac_bits;
  if constexpr (V == DepthVariant::Stable) {
    const T q = b >= 0 ? -(b + sq) : -(b - sq);
    if (q == 0) {  // b = 0 and Δ = 0
      if (s.a != 0) {
        r.count = 1;
        r.z[0] = std::int64_t(s.z0);
      }
      return r;
    }
    const T a = T(s.a);
    if (a == 0) {
      r.count = 1;
      r.z[0] = windowDepth(divRoundT<T>(shlT<T>(c, Fz), q, R));
      return r;
    }
    std::int64_t z1;
    if constexpr (sizeof(T) == sizeof(std::int64_t))
      z1 = windowDepth(divRound64ByReciprocal(shlT<T>(q, Fz), a, invAbsA, R));
    else
      z1 = windowDepth(divRound(shlT<T>(q, Fz), a, R));
    std::int64_t z2 = windowDepth(divRoundT<T>(shlT<T>(c, Fz), q, R));
    if (z2 < z1) std::swap(z1, z2);
    r.count = 2;
    r.z[0] = z1;
    r.z[1] = z2;
    return r;
  } else {
    if (!s.recipValid) return r;
    const int sh = s.recipShift - Fz;
    const i128 m = i128(T(s.recipM));
    std::int64_t z1 = windowDepth(shiftRoundR<R>(i128(-b - sq) * m, sh));
    std::int64_t z2 = windowDepth(shiftRoundR<R>(i128(-b + sq) * m, sh));
    if (z2 < z1) std::swap(z1, z2);
    r.count = 2;
    r.z[0] = z1;
    r.z[1] = z2;
    return r;
  }
}

}  // namespace qacc
