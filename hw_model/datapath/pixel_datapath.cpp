#include "hw_model/datapath/pixel_datapath.h"

#include "hw_model/datapath/cap_select.h"
#include "hw_model/datapath/clip_test.h"
#include "hw_model/datapath/depth_roots.h"
#include "hw_model/datapath/sqrt_extractor.h"

namespace qacc {

namespace {

// The b and c interpolators' accumulators in 64-bit registers: every value they take at a
// position of the box, u in [0, x1 - x0] (the last step of a span lands on x1 - x0) and v in
// [0, y1 - y0), every forward difference there and 2A are below 2^62 in magnitude (the sums
// of the coefficients' magnitudes times the powers of the box's sides bound them; at most
// about 2^104 for 74-bit coefficients on a 2^14-pixel side, kMaxImageSide, so the bound
// itself fits i128). The 64-bit path runs only on spans within the box (evaluateSpanT).
bool interpolatorsFit64(const PrimitiveSetup& s) {
  const i128 U = s.x1 - s.x0, V = s.y1 - s.y0, lim = i128(1) << 62;
  const auto mag = [](i128 x) { return x < 0 ? -x : x; };
  const LinearCoefficients& b = s.b;
  const QuadraticCoefficients& c = s.c;
  const i128 bMax = mag(b.A) * U + mag(b.B) * V + mag(b.C);
  const i128 cMax = mag(c.A) * U * U + mag(c.B) * U * V + mag(c.C) * V * V + mag(c.D) * U + mag(c.E) * V + mag(c.F);
  const i128 stepMax = mag(c.A) * (2 * U + 1) + mag(c.B) * V + mag(c.D);
  return bMax < lim && cMax < lim && stepMax < lim && 2 * mag(c.A) < lim;
}

// Whether primitive s's quadric datapath fits 64-bit host registers (depthRootsT's T, and
// √Δ before it), so that evaluateSpan computes it in std::int64_t — the same values:
//  - b, c and √Δ are value_bits + 1 registers (|x| <= 2^value_bits); the stable variant's
//    dividends q · 2^Fz and c · 2^Fz stay below 2^62, divRound64's domain, when
//    value_bits + 1 + depth_frac_bits <= 62 (the default: 32 + 1 + 28 = 61);
//  - the extractor's root sd < 2^(H + 1/2), H = ceil(delta_bits / 2) (its operand is below
//    2^(delta_bits + 1): a wrapped Δ register is read as its bits, SqrtExtractor::operand), scaled
//    by 2^-(ed - e): a left shift by k = e - ed stays below 2^62.5 < 2^63 when H + k <= 62, a right
//    shift (and its rounding half 2^(shift-1)) is exact in 64 bits up to shift 62;
//  - the depth unit's constants: a (a value_bits register), recipM (a recip_bits mantissa),
//    0 <= z0 <= 2^Fz and 0 <= zShift <= Fz / 2 from setup, checked here all the same, so
//    that z0 + t 2^-zShift of a clamped t (depth_bits <= 40) cannot leave 64 bits;
//  - the b and c accumulators (interpolatorsFit64).
bool fits64(const PrimitiveSetup& s, const HwConfig& cfg) {
  if (cfg.value_bits + 1 + cfg.depth_frac_bits > 62) return false;
  const int H = (cfg.delta_bits + 1) / 2, shift = s.ed - s.e;
  if (shift < 0 ? H - shift > 62 : shift > 62) return false;
  const i128 z0Max = i128(1) << 41, kMax = i128(1) << 62;
  return s.z0 >= -z0Max && s.z0 <= z0Max && s.zShift >= 0 && s.zShift <= 20 && s.a > -kMax && s.a < kMax &&
         s.recipM > -kMax && s.recipM < kMax && interpolatorsFit64(s);
}

}  // namespace

PixelDatapath::PixelDatapath(const HwConfig& cfg) : cfg_(cfg) {
  hRange_ = WidthRange(cfg.clip_bits + cfg.interp_frac_bits + 2);
  valueRange_ = WidthRange(cfg.value_bits + 1);
  deltaRange_ = WidthRange(cfg.delta_bits + 1);
  accRange_ = WidthRange(cfg.interp_acc_bits);
  depthHi_ = (i128(1) << (cfg.depth_bits - 1)) - 1;
  depthLo_ = -depthHi_ - 1;
}

PixelDatapath::PixelDatapath(const PrimitiveSetup& s, const HwConfig& cfg) : PixelDatapath(cfg) { load(s); }

int PixelDatapath::clipPassesOf(const PrimitiveSetup& s, const HwConfig& cfg) {
  return ClipTest::passes(int(s.planes.size()), cfg.clip_evaluators) + (s.solid && !s.facet ? 1 : 0);
}

void PixelDatapath::load(const PrimitiveSetup& s) {
  s_ = &s;
  delta_ = QuadraticInterpolator(s.delta, cfg_.interp_frac_bits, cfg_.interp_acc_bits);
  c_ = QuadraticInterpolator(s.c, cfg_.interp_frac_bits, cfg_.interp_acc_bits);
  b_ = LinearInterpolator(s.b);
  facetZ_ = LinearInterpolator(s.facetZ);
  h_.clear();
  zk_.clear();
  for (const PlaneSetup& p : s.planes) {
    h_.emplace_back(p.h);
    zk_.emplace_back(p.zk);
  }
  hv_.resize(s.planes.size());
  zkv_.resize(s.planes.size());
  narrow_ = !s.facet && fits64(s, cfg_);
  clipPasses_ = clipPassesOf(s, cfg_);
  invAbsA_ = s.a != 0 ? 1.0 / double(s.a < 0 ? -s.a : s.a) : 0.0;
  const bool stable = cfg_.depth_variant == DepthVariant::Stable;
  switch (cfg_.rounding) {
    case Rounding::Truncate:
      stable ? choosePaths<Rounding::Truncate, DepthVariant::Stable>()
             : choosePaths<Rounding::Truncate, DepthVariant::Reciprocal>();
      break;
    case Rounding::Nearest:
      stable ? choosePaths<Rounding::Nearest, DepthVariant::Stable>()
             : choosePaths<Rounding::Nearest, DepthVariant::Reciprocal>();
      break;
    case Rounding::NearestEven:
      stable ? choosePaths<Rounding::NearestEven, DepthVariant::Stable>()
             : choosePaths<Rounding::NearestEven, DepthVariant::Reciprocal>();
      break;
  }
}

template <Rounding R, DepthVariant V>
void PixelDatapath::choosePaths() {
  using I64 = std::int64_t;
  evalFloored_ = &PixelDatapath::evaluateFloored<R, V, Shape::Any, i128>;
  if (s_->facet)  // no rounding, no depth unit, no quadric registers: one instance serves all modes
    evalSpan_ = &PixelDatapath::evaluateSpanT<Rounding::Nearest, DepthVariant::Stable, Shape::Facet, i128>;
  else if (s_->solid)
    evalSpan_ = narrow_ ? &PixelDatapath::evaluateSpanT<R, V, Shape::Solid, I64>
                        : &PixelDatapath::evaluateSpanT<R, V, Shape::Solid, i128>;
  else
    evalSpan_ = narrow_ ? &PixelDatapath::evaluateSpanT<R, V, Shape::Surface, I64>
                        : &PixelDatapath::evaluateSpanT<R, V, Shape::Surface, i128>;
}

// The span loop's parts are inlined into it (evaluateSpanT), so that nothing is called per pixel.
template <PixelDatapath::Shape S, typename T>
[[gnu::always_inline]] inline void PixelDatapath::startSpanT(int u, int v) {
  const bool facet = S == Shape::Facet || (S == Shape::Any && s_->facet);
  const bool solid = S == Shape::Solid || (S == Shape::Any && s_->solid);
  if (facet) {
    facetZ_.start(u, v);
  } else if constexpr (sizeof(T) == sizeof(std::int64_t)) {  // b and c in 64-bit registers
    delta_.start(u, v);
    const QuadraticCoefficients& k = s_->c;
    c64_ = std::int64_t(c_.direct(u, v));
    cStep64_ = std::int64_t(k.A * (2 * i128(u) + 1) + k.B * i128(v) + k.D);
    c2A64_ = std::int64_t(2 * k.A);
    b64_ = std::int64_t(b_.direct(u, v));
    bA64_ = std::int64_t(s_->b.A);
  } else {
    delta_.start(u, v);
    c_.start(u, v);
    b_.start(u, v);
  }
  for (std::size_t i = 0; i < h_.size(); ++i) {
    h_[i].start(u, v);
    if (solid) zk_[i].start(u, v);
  }
}

template <PixelDatapath::Shape S, typename T>
[[gnu::always_inline]] inline void PixelDatapath::stepRightT() {
  const bool facet = S == Shape::Facet || (S == Shape::Any && s_->facet);
  const bool solid = S == Shape::Solid || (S == Shape::Any && s_->solid);
  if (facet) {
    facetZ_.stepRight();
  } else if constexpr (sizeof(T) == sizeof(std::int64_t)) {  // QuadraticInterpolator::stepRight
    delta_.stepRight();
    c64_ += cStep64_;
    cStep64_ += c2A64_;
    b64_ += bA64_;
  } else {
    delta_.stepRight();
    c_.stepRight();
    b_.stepRight();
  }
  for (std::size_t i = 0; i < h_.size(); ++i) {
    h_[i].stepRight();
    if (solid) zk_[i].stepRight();
  }
}

void PixelDatapath::startSpan(int u, int v) { startSpanT<Shape::Any>(u, v); }
void PixelDatapath::stepRight() { stepRightT<Shape::Any>(); }

PixelOutcome PixelDatapath::evaluate(OverflowCounters& ovf) { return (this->*evalFloored_)(ovf); }

template <Rounding R, DepthVariant V, PixelDatapath::Shape S, typename T>
void PixelDatapath::evaluateSpanT(int u, int v, int n, PixelOutcome* out, OverflowCounters& ovf) {
  if constexpr (sizeof(T) == sizeof(std::int64_t)) {  // the 64-bit accumulators' bound holds in the box
    if (u < 0 || v < 0 || u + n > s_->x1 - s_->x0 || v >= s_->y1 - s_->y0)
      return evaluateSpanT<R, V, S, i128>(u, v, n, out, ovf);
  }
  startSpanT<S, T>(u, v);
  for (int i = 0; i < n; ++i) {
    out[i] = evaluateFloored<R, V, S, T>(ovf);
    stepRightT<S, T>();
  }
}

template <Rounding R, DepthVariant V, PixelDatapath::Shape S, typename T>
[[gnu::always_inline]] inline PixelOutcome PixelDatapath::evaluateFloored(OverflowCounters& ovf) {
  PixelOutcome o = evaluateUnfloored<R, V, S, T>(ovf);
  // The depth floor (PrimitiveSetup::zFloor): one comparator and a multiplexer after the
  // depth unit, so that the floor bounds every depth of the primitive (hierarchical Z).
  if (o.hit && o.z < s_->zFloor) {
    ++ovf.depth_floor_clamps;
    o.z = s_->zFloor;
  }
  return o;
}

template <Rounding R, DepthVariant V, PixelDatapath::Shape S, typename T>
[[gnu::always_inline]] inline PixelOutcome PixelDatapath::evaluateUnfloored(OverflowCounters& ovf) {
  const PrimitiveSetup& s = *s_;
  const bool facet = S == Shape::Facet || (S == Shape::Any && s.facet);
  const bool solid = S == Shape::Solid || (S == Shape::Any && s.solid);
  PixelOutcome o;
  const int Fz = cfg_.depth_frac_bits, Fi = cfg_.interp_frac_bits;
  const std::int64_t one = std::int64_t(1) << Fz;
  const int np = int(h_.size());
  o.clipPasses = clipPasses_;
  for (int i = 0; i < np; ++i) hv_[std::size_t(i)] = hRange_.fit(h_[std::size_t(i)].raw(), cfg_.overflow, ovf.clip);
  // clampDepth's result, its bounds precomputed (the call only when a clamp happens).
  const auto depth = [&](i128 z) { return z >= depthLo_ && z <= depthHi_ ? z : clampDepth(z, cfg_, ovf); };

  if (facet) {
    const i128 z = depth(facetZ_.raw() >> Fi);
    o.candidate = true;
    if (z >= 0 && z <= one && ClipTest::keptByAll(s.planes, hv_.data(), z, Fz)) {
      o.hit = true;
      o.z = z;
    }
    return o;
  }

  T b, c;
  if constexpr (sizeof(T) == sizeof(std::int64_t)) {  // the 64-bit accumulators: the same values
    b = valueRange_.fitT<T>(b64_ >> Fi, cfg_.overflow, ovf.interpolator);
    c = valueRange_.fitT<T>(c64_ >> Fi, cfg_.overflow, ovf.interpolator);
  } else {
    b = T(valueRange_.fit(b_.raw() >> Fi, cfg_.overflow, ovf.interpolator));
    c = T(valueRange_.fit(c_.raw() >> Fi, cfg_.overflow, ovf.interpolator));
  }
  if (solid) {
    for (int i = 0; i < np; ++i)
      zkv_[std::size_t(i)] = s.planes[std::size_t(i)].zdir != 0 ? depth(zk_[std::size_t(i)].raw() >> Fi) : 0;
    const CapDecision d = CapSelect::decide(s, cfg_, zkv_.data(), hv_.data(), b, c);
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
  const T sd = T(SqrtExtractor::compute(SqrtExtractor::operand(din, deltaRange_.width)));
  const T sq = valueRange_.fitT<T>(shiftRoundR<R>(sd, s.ed - s.e), cfg_.overflow, ovf.sqrt);
  const DepthRoots r = depthRootsT<R, V, T>(s, cfg_, b, c, sq, ovf, invAbsA_);
  for (int k = 0; k < r.count; ++k) {
    const std::int64_t z = r.z[k];
    if (z >= 0 && z <= one && ClipTest::keptByAll(s.planes, hv_.data(), z, Fz)) {
      o.hit = true;
      o.z = z;
      return o;
    }
  }
  return o;
}

}  // namespace qacc
