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

#include "hw_model/config/hw_config.h"
#include "hw_model/datapath/overflow_counters.h"
#include "hw_model/datapath/primitive_setup.h"

namespace qacc {

struct DepthRoots {
  int count = 0;
  i128 z[2] = {0, 0};  // ascending
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

}  // namespace qacc
