// PixelDatapath::solidIntervals (pixel_datapath.h): the whole depth intervals of a solid
// on the current pixel's line, for CSG. Same arithmetic as evaluate(): the clip planes'
// depths zk bound the line to [lo, hi] (CapSelect's interval logic), Δ, the square root
// and the depth unit give the quadric's roots, and the sign of a says whether {f <= 0}
// is between the roots or outside them.
#include <limits>

#include "hw_model/datapath/clip_test.h"
#include "hw_model/datapath/depth_roots.h"
#include "hw_model/datapath/pixel_datapath.h"
#include "hw_model/datapath/sqrt_extractor.h"

namespace qacc {

int PixelDatapath::solidIntervals(OverflowCounters& ovf, FixedDepthInterval out[2]) {
  constexpr int kSurface = -1, kView = -2;
  const int Fz = cfg_.depth_frac_bits, Fi = cfg_.interp_frac_bits;
  const int np = int(h_.size());
  const int hw = cfg_.clip_bits + Fi + 2;
  for (int i = 0; i < np; ++i) hv_[std::size_t(i)] = fitWidth(h_[std::size_t(i)].raw(), hw, cfg_.overflow, ovf.clip);

  FixedDepthBound lo{0, kView}, hi{i128(1) << Fz, kView};
  for (int i = 0; i < np; ++i) {
    const PlaneSetup& p = s_->planes[std::size_t(i)];
    if (p.zdir == 0) {
      if (!ClipTest::keeps(p, hv_[std::size_t(i)], 0, Fz)) return 0;
      continue;
    }
    const i128 zk = clampDepth(zk_[std::size_t(i)].raw() >> Fi, cfg_, ovf);
    if (p.zdir < 0 && zk > lo.z) lo = {zk, i};
    if (p.zdir > 0 && zk < hi.z) hi = {zk, i};
  }
  if (lo.z > hi.z) return 0;

  const int vw = cfg_.value_bits + 1;
  const i128 b = fitWidth(b_.raw() >> Fi, vw, cfg_.overflow, ovf.interpolator);
  const i128 c = fitWidth(c_.raw() >> Fi, vw, cfg_.overflow, ovf.interpolator);
  const i128 ninf = std::numeric_limits<i128>::min(), pinf = std::numeric_limits<i128>::max();
  i128 piece[2][2];
  int pieces = 0;
  auto add = [&](i128 z0, i128 z1) {
    piece[pieces][0] = z0;
    piece[pieces++][1] = z1;
  };
  const i128 delta = delta_.output(cfg_.overflow, ovf.interpolator);
  if (delta < 0) {
    if (s_->a < 0) add(ninf, pinf);  // no root and f < 0 everywhere on the line
  } else {
    const i128 din = fitWidth(delta, cfg_.delta_bits + 1, cfg_.overflow, ovf.sqrt);
    const i128 sd = i128(SqrtExtractor::compute(SqrtExtractor::operand(din, cfg_.delta_bits + 1)));
    const i128 sq = fitWidth(shiftRound(sd, s_->ed - s_->e, cfg_.rounding), vw, cfg_.overflow, ovf.sqrt);
    const DepthRoots r = depthRoots(*s_, cfg_, b, c, sq, ovf);
    if (r.count == 2) {
      if (s_->a > 0) {
        add(r.z[0], r.z[1]);
      } else {
        add(ninf, r.z[0]);
        add(r.z[1], pinf);
      }
    } else if (r.count == 1) {
      if (s_->a == 0) {  // linear along the line: 2 b z + c <= 0
        if (b > 0) add(ninf, r.z[0]);
        else add(r.z[0], pinf);
      } else if (s_->a < 0) {
        add(ninf, pinf);  // double root of a concave f: f <= 0 everywhere
      }
    } else if (s_->a == 0 && b == 0 && c <= 0) {
      add(ninf, pinf);
    }
  }

  int n = 0;
  for (int k = 0; k < pieces; ++k) {
    FixedDepthInterval iv;
    iv.in = lo.z >= piece[k][0] ? lo : FixedDepthBound{piece[k][0], kSurface};
    iv.out = hi.z <= piece[k][1] ? hi : FixedDepthBound{piece[k][1], kSurface};
    if (iv.in.z < iv.out.z) out[n++] = iv;
  }
  return n;
}

}  // namespace qacc
