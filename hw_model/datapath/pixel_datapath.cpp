#include "hw_model/datapath/pixel_datapath.h"

#include "hw_model/datapath/cap_select.h"
#include "hw_model/datapath/clip_test.h"
#include "hw_model/datapath/depth_roots.h"
#include "hw_model/datapath/sqrt_extractor.h"

namespace qacc {

PixelDatapath::PixelDatapath(const PrimitiveSetup& s, const HwConfig& cfg)
    : s_(s), cfg_(cfg), delta_(s.delta, cfg.interp_frac_bits, cfg.interp_acc_bits),
      c_(s.c, cfg.interp_frac_bits, cfg.interp_acc_bits), b_(s.b), facetZ_(s.facetZ) {
  for (const PlaneSetup& p : s.planes) {
    h_.emplace_back(p.h);
    zk_.emplace_back(p.zk);
  }
  hv_.resize(s.planes.size());
  zkv_.resize(s.planes.size());
}

void PixelDatapath::startSpan(int u, int v) {
  if (s_.facet) {
    facetZ_.start(u, v);
  } else {
    delta_.start(u, v);
    c_.start(u, v);
    b_.start(u, v);
  }
  for (std::size_t i = 0; i < h_.size(); ++i) {
    h_[i].start(u, v);
    if (s_.solid) zk_[i].start(u, v);
  }
}

void PixelDatapath::stepRight() {
  if (s_.facet) {
    facetZ_.stepRight();
  } else {
    delta_.stepRight();
    c_.stepRight();
    b_.stepRight();
  }
  for (std::size_t i = 0; i < h_.size(); ++i) {
    h_[i].stepRight();
    if (s_.solid) zk_[i].stepRight();
  }
}

PixelOutcome PixelDatapath::evaluate(OverflowCounters& ovf) {
  PixelOutcome o;
  const int Fz = cfg_.depth_frac_bits, Fi = cfg_.interp_frac_bits;
  const i128 one = i128(1) << Fz;
  const int np = int(h_.size());
  o.clipPasses = ClipTest::passes(np, cfg_.clip_evaluators);
  const int hw = cfg_.clip_bits + Fi + 2;
  for (int i = 0; i < np; ++i) hv_[std::size_t(i)] = fitWidth(h_[std::size_t(i)].raw(), hw, cfg_.overflow, ovf.clip);

  if (s_.facet) {
    const i128 z = clampDepth(facetZ_.raw() >> Fi, cfg_, ovf);
    o.candidate = true;
    if (z >= 0 && z <= one && ClipTest::keptByAll(s_.planes, hv_.data(), z, Fz)) {
      o.hit = true;
      o.z = z;
    }
    return o;
  }

  const int vw = cfg_.value_bits + 1;
  const i128 b = fitWidth(b_.raw() >> Fi, vw, cfg_.overflow, ovf.interpolator);
  const i128 c = fitWidth(c_.raw() >> Fi, vw, cfg_.overflow, ovf.interpolator);
  if (s_.solid) {
    for (int i = 0; i < np; ++i)
      zkv_[std::size_t(i)] = s_.planes[std::size_t(i)].zdir != 0
                                 ? clampDepth(zk_[std::size_t(i)].raw() >> Fi, cfg_, ovf)
                                 : 0;
    o.clipPasses += 1;
    const CapDecision d = CapSelect::decide(s_, cfg_, zkv_.data(), hv_.data(), b, c);
    if (d.empty) {
      o.candidate = d.plane >= 0;
      return o;
    }
    if (d.cap) {
      o.candidate = o.hit = true;
      o.cap = d.plane;
      o.z = d.z;
      return o;
    }
  }
  // Δ >= 0 decides coverage, exactly, from the quadratic interpolator.
  const i128 delta = delta_.output(cfg_.overflow, ovf.interpolator);
  if (delta < 0) return o;
  o.candidate = true;
  const i128 din = fitWidth(delta, cfg_.delta_bits + 1, cfg_.overflow, ovf.sqrt);
  const i128 sd = i128(SqrtExtractor::compute((unsigned __int128)din));
  const i128 sq = fitWidth(shiftRound(sd, s_.ed - s_.e, cfg_.rounding), vw, cfg_.overflow, ovf.sqrt);
  const DepthRoots r = depthRoots(s_, cfg_, b, c, sq, ovf);
  for (int k = 0; k < r.count; ++k) {
    const i128 z = r.z[k];
    if (z >= 0 && z <= one && ClipTest::keptByAll(s_.planes, hv_.data(), z, Fz)) {
      o.hit = true;
      o.z = z;
      return o;
    }
  }
  return o;
}

}  // namespace qacc
