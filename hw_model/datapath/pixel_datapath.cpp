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
  hRange_ = WidthRange(cfg.clip_bits + cfg.interp_frac_bits + 2);
  valueRange_ = WidthRange(cfg.value_bits + 1);
  deltaRange_ = WidthRange(cfg.delta_bits + 1);
  accRange_ = WidthRange(cfg.interp_acc_bits);
  depthHi_ = (i128(1) << (cfg.depth_bits - 1)) - 1;
  depthLo_ = -depthHi_ - 1;
  const bool stable = cfg.depth_variant == DepthVariant::Stable;
  switch (cfg.rounding) {
    case Rounding::Truncate:
      evalFloored_ = stable ? &PixelDatapath::evaluateFloored<Rounding::Truncate, DepthVariant::Stable>
                            : &PixelDatapath::evaluateFloored<Rounding::Truncate, DepthVariant::Reciprocal>;
      break;
    case Rounding::Nearest:
      evalFloored_ = stable ? &PixelDatapath::evaluateFloored<Rounding::Nearest, DepthVariant::Stable>
                            : &PixelDatapath::evaluateFloored<Rounding::Nearest, DepthVariant::Reciprocal>;
      break;
    case Rounding::NearestEven:
      evalFloored_ = stable ? &PixelDatapath::evaluateFloored<Rounding::NearestEven, DepthVariant::Stable>
                            : &PixelDatapath::evaluateFloored<Rounding::NearestEven, DepthVariant::Reciprocal>;
      break;
  }
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

PixelOutcome PixelDatapath::evaluate(OverflowCounters& ovf) { return (this->*evalFloored_)(ovf); }

template <Rounding R, DepthVariant V>
PixelOutcome PixelDatapath::evaluateFloored(OverflowCounters& ovf) {
  PixelOutcome o = evaluateUnfloored<R, V>(ovf);
  // The depth floor (PrimitiveSetup::zFloor): one comparator and a multiplexer after the
  // depth unit, so that the floor bounds every depth of the primitive (hierarchical Z).
  if (o.hit && o.z < s_.zFloor) {
    ++ovf.depth_floor_clamps;
    o.z = s_.zFloor;
  }
  return o;
}

template <Rounding R, DepthVariant V>
PixelOutcome PixelDatapath::evaluateUnfloored(OverflowCounters& ovf) {
  PixelOutcome o;
  const int Fz = cfg_.depth_frac_bits, Fi = cfg_.interp_frac_bits;
  const i128 one = i128(1) << Fz;
  const int np = int(h_.size());
  o.clipPasses = ClipTest::passes(np, cfg_.clip_evaluators);
  for (int i = 0; i < np; ++i) hv_[std::size_t(i)] = hRange_.fit(h_[std::size_t(i)].raw(), cfg_.overflow, ovf.clip);
  // clampDepth's result, its bounds precomputed (the call only when a clamp happens).
  const auto depth = [&](i128 z) { return z >= depthLo_ && z <= depthHi_ ? z : clampDepth(z, cfg_, ovf); };

  if (s_.facet) {
    const i128 z = depth(facetZ_.raw() >> Fi);
    o.candidate = true;
    if (z >= 0 && z <= one && ClipTest::keptByAll(s_.planes, hv_.data(), z, Fz)) {
      o.hit = true;
      o.z = z;
    }
    return o;
  }

  const i128 b = valueRange_.fit(b_.raw() >> Fi, cfg_.overflow, ovf.interpolator);
  const i128 c = valueRange_.fit(c_.raw() >> Fi, cfg_.overflow, ovf.interpolator);
  if (s_.solid) {
    for (int i = 0; i < np; ++i)
      zkv_[std::size_t(i)] = s_.planes[std::size_t(i)].zdir != 0
                                 ? depth(zk_[std::size_t(i)].raw() >> Fi)
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
  // (QuadraticInterpolator::output, the accumulator's range precomputed.)
  const i128 delta = accRange_.fit(delta_.raw(), cfg_.overflow, ovf.interpolator) >> delta_.frac();
  if (delta < 0) return o;
  o.candidate = true;
  const i128 din = deltaRange_.fit(delta, cfg_.overflow, ovf.sqrt);
  const i128 sd = i128(SqrtExtractor::compute((unsigned __int128)din));
  const i128 sq = valueRange_.fit(shiftRoundR<R>(sd, s_.ed - s_.e), cfg_.overflow, ovf.sqrt);
  const DepthRoots r = depthRootsT<R, V>(s_, cfg_, b, c, sq, ovf);
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
