// CapSelect: solid display (digest §1, "surface vs volume"): where the line of a pixel
// enters the solid {f <= 0} ∩ clip polyhedron through one of the primitive's own clip
// planes, the visible point is a cap on that plane. Depth-interval logic on the plane
// depths zk(u, v) (linear interpolators): entry lo = the largest lower bound (planes
// with pz < 0, and the near plane), exit hi = the smallest upper bound; the cap is shown
// when lo comes from a plane, lo <= hi, f(lo) <= 0 (exact integer evaluation of
// a lo² + 2 b lo + c) and every other plane keeps lo. Same decisions as the reference
// (raster/pixel_hit.h), in the fixed-point formats.
#pragma once
#include "hw_model/datapath/clip_test.h"
#include "hw_model/config/hw_config.h"

namespace qacc {

struct CapDecision {
  bool empty = false;  // the clip interval is empty: nothing visible on this line
  bool cap = false;
  int plane = -1;
  i128 z = 0;
};

struct CapSelect {
  // zk: the planes' depths (depth format), hRaw: their h values; a, b, c at the block scale.
  static CapDecision decide(const PrimitiveSetup& s, const HwConfig& cfg, const i128* zk, const i128* hRaw, i128 b,
                            i128 c) {
    CapDecision d;
    const int Fz = cfg.depth_frac_bits;
    i128 lo = 0, hi = i128(1) << Fz;
    int loPlane = -1;
    for (std::size_t i = 0; i < s.planes.size(); ++i) {
      const PlaneSetup& p = s.planes[i];
      if (p.zdir < 0) {
        if (zk[i] > lo) {
          lo = zk[i];
          loPlane = int(i);
        }
      } else if (p.zdir > 0) {
        if (zk[i] < hi) hi = zk[i];
      } else if (!ClipTest::keeps(p, hRaw[i], 0, Fz)) {
        d.empty = true;
        return d;
      }
    }
    if (lo > hi) {
      d.empty = true;
      return d;
    }
    if (loPlane >= 0) {
      // f(lo) · 2^(e + 2 Fz) = a lo² + 2 b lo 2^Fz + c 2^(2 Fz)
      const i128 f = s.a * lo * lo + shl(2 * b * lo, Fz) + shl(c, 2 * Fz);
      if (f <= 0 && ClipTest::keptByAll(s.planes, hRaw, lo, Fz, loPlane)) {
        d.cap = true;
        d.plane = loPlane;
        d.z = lo;
      }
    }
    return d;
  }
};

}  // namespace qacc
