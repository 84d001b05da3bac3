#include "hw_model/datapath/depth_roots.h"

#include <utility>

namespace qacc {

namespace {
// A root t (depth format, t units) as window depth z = z0 + t 2^-zShift.
i128 windowDepth(const PrimitiveSetup& s, const HwConfig& cfg, i128 t, OverflowCounters& ovf) {
  const i128 z = s.z0 + shiftRound(clampDepth(t, cfg, ovf), s.zShift, cfg.rounding);
  const i128 hi = (i128(1) << (cfg.depth_bits - 1)) - 1;
  return z > hi ? hi : (z < -hi - 1 ? -hi - 1 : z);
}
}  // namespace

DepthRoots depthRoots(const PrimitiveSetup& s, const HwConfig& cfg, i128 b, i128 c, i128 sq, OverflowCounters& ovf) {
  DepthRoots r;
  const int Fz = cfg.depth_frac_bits;
  if (cfg.depth_variant == DepthVariant::Stable) {
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
      r.z[0] = windowDepth(s, cfg, divRound(shl(c, Fz), q, cfg.rounding), ovf);
      return r;
    }
    i128 z1 = windowDepth(s, cfg, divRound(shl(q, Fz), s.a, cfg.rounding), ovf);
    i128 z2 = windowDepth(s, cfg, divRound(shl(c, Fz), q, cfg.rounding), ovf);
    if (z2 < z1) std::swap(z1, z2);
    r.count = 2;
    r.z[0] = z1;
    r.z[1] = z2;
    return r;
  }
  if (!s.recipValid) return r;
  const int sh = s.recipShift - Fz;
  i128 z1 = windowDepth(s, cfg, shiftRound((-b - sq) * s.recipM, sh, cfg.rounding), ovf);
  i128 z2 = windowDepth(s, cfg, shiftRound((-b + sq) * s.recipM, sh, cfg.rounding), ovf);
  if (z2 < z1) std::swap(z1, z2);
  r.count = 2;
  r.z[0] = z1;
  r.z[1] = z2;
  return r;
}

}  // namespace qacc
