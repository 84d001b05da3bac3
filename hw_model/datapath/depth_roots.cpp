#include "hw_model/datapath/depth_roots.h"

#include <utility>

namespace qacc {

DepthRoots depthRoots(const PrimitiveSetup& s, const HwConfig& cfg, i128 b, i128 c, i128 sq, OverflowCounters& ovf) {
  DepthRoots r;
  const int Fz = cfg.depth_frac_bits;
  if (cfg.depth_variant == DepthVariant::Stable) {
    const i128 q = b >= 0 ? -(b + sq) : -(b - sq);
    if (q == 0) {  // b = 0 and Δ = 0
      if (s.a != 0) {
        r.count = 1;
        r.z[0] = 0;
      }
      return r;
    }
    if (s.a == 0) {
      r.count = 1;
      r.z[0] = clampDepth(divRound(shl(c, Fz), q, cfg.rounding), cfg, ovf);
      return r;
    }
    i128 z1 = clampDepth(divRound(shl(q, Fz), s.a, cfg.rounding), cfg, ovf);
    i128 z2 = clampDepth(divRound(shl(c, Fz), q, cfg.rounding), cfg, ovf);
    if (z2 < z1) std::swap(z1, z2);
    r.count = 2;
    r.z[0] = z1;
    r.z[1] = z2;
    return r;
  }
  if (!s.recipValid) return r;
  const int sh = s.recipShift - Fz;
  i128 z1 = clampDepth(shiftRound((-b - sq) * s.recipM, sh, cfg.rounding), cfg, ovf);
  i128 z2 = clampDepth(shiftRound((-b + sq) * s.recipM, sh, cfg.rounding), cfg, ovf);
  if (z2 < z1) std::swap(z1, z2);
  r.count = 2;
  r.z[0] = z1;
  r.z[1] = z2;
  return r;
}

}  // namespace qacc
