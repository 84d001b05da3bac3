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
template <Rounding R, DepthVariant V>
inline DepthRoots depthRootsT(const PrimitiveSetup& s, const HwConfig& cfg, i128 b, i128 c, i128 sq,
                              OverflowCounters& ovf) {
  // A root t (depth format, t units) as window depth z = z0 + t 2^-zShift.
  const i128 hi = (i128(1) << (cfg.depth_bits - 1)) - 1;
  const auto windowDepth = [&](i128 t) {
    const i128 z = s.z0 + shiftRoundR<R>(clampDepth(t, cfg, ovf), s.zShift);
    return z > hi ? hi : (z < -hi - 1 ? -hi - 1 : z);
  };
  DepthRoots r;
  const int Fz = cfg.depth_frac_bits;
  if constexpr (V == DepthVariant::Stable) {
    const i128 q = b >= 0 ? -(b + sq) : -(b - sq);
    if (q == 0) {  // b = 0 and Δ = 0
      if (s.a != 0) {
        r.count = 1;
        r.z[0] = s.z0;
      }
      return r;
    }
    if (s.a == 0) {
      r.count = 1;
      r.z[0] = std::int64_t(windowDepth(divRound(shl(c, Fz), q, R)));
      return r;
    }
    std::int64_t z1 = std::int64_t(windowDepth(divRound(shl(q, Fz), s.a, R)));
    std::int64_t z2 = std::int64_t(windowDepth(divRound(shl(c, Fz), q, R)));
    if (z2 < z1) std::swap(z1, z2);
    r.count = 2;
    r.z[0] = z1;
    r.z[1] = z2;
    return r;
  } else {
    if (!s.recipValid) return r;
    const int sh = s.recipShift - Fz;
    std::int64_t z1 = std::int64_t(windowDepth(shiftRoundR<R>((-b - sq) * s.recipM, sh)));
    std::int64_t z2 = std::int64_t(windowDepth(shiftRoundR<R>((-b + sq) * s.recipM, sh)));
    if (z2 < z1) std::swap(z1, z2);
    r.count = 2;
    r.z[0] = z1;
    r.z[1] = z2;
    return r;
  }
}

}  // namespace qacc
