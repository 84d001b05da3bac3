// PixelDatapath: the arithmetic of one pixel pipeline (design §3.2 step 4) for one
// primitive — interpolators (Δ, b, c quadratic/linear; clip planes h; plane depths zk;
// facet depth), square-root extractor, depth unit, clip unit and caps — producing the
// visible point of the primitive on the line of a pixel, in fixed point.
// startSpan() loads the interpolators directly at a pixel; along the span they advance
// by forward differences (stepRight; the same values, bit for bit). Both engines call
// exactly this code (hw per tile, hw-cycle in its pixel datapath pass,
// engines/pixel_trace.h); the pixel pipeline unit (timing/pixel_pipeline_unit.h) only adds
// time around it.
#pragma once
#include <vector>

#include "hw_model/config/hw_config.h"
#include "hw_model/datapath/overflow_counters.h"
#include "hw_model/datapath/linear_interpolator.h"
#include "hw_model/datapath/primitive_setup.h"
#include "hw_model/datapath/quadratic_interpolator.h"

namespace qacc {

struct PixelOutcome {
  bool candidate = false;  // Δ >= 0, a cap candidate, or a facet pixel: a point to clip
  bool hit = false;        // a visible point survived clipping
  int cap = -1;            // plane index of a cap, -1 for a surface point
  i128 z = 0;              // depth, internal format
  int clipPasses = 0;      // passes through the clip unit
};

// One end of a solid's depth interval on a pixel's line, in the depth format: the
// quadric surface (tag -1), the near or far plane (tag -2) or clip plane `tag` (a cap).
struct FixedDepthBound {
  i128 z = 0;
  int tag = -1;
};
struct FixedDepthInterval {
  FixedDepthBound in, out;
};

class PixelDatapath {
 public:
  // A pipeline of the configuration with no primitive yet: load() one before use.
  explicit PixelDatapath(const HwConfig& cfg);
  PixelDatapath(const PrimitiveSetup& s, const HwConfig& cfg);  // PixelDatapath(cfg), then load(s)
  // The setup unit loads the pipeline with a primitive: its interpolator seeds and planes.
  // The storage is reused, so an engine keeps one datapath per thread and loads every
  // (primitive, tile) into it without allocating. `s` must outlive its use here.
  void load(const PrimitiveSetup& s);
  void startSpan(int u, int v);
  void stepRight();
  // At the current position; a visible depth is never below the primitive's depth floor
  // (PrimitiveSetup::zFloor): one nearer is raised to it and counted (depth_floor_clamps).
  // The straightforward datapath, as the hardware computes it: every register 128 bits on
  // the host, the primitive's kind (facet, solid) tested at every pixel.
  PixelOutcome evaluate(OverflowCounters& ovf);
  // The n pixels (u, v), (u + 1, v), ... of a span: out[i] is what startSpan(u, v), then i
  // stepRight() and evaluate() give, bit for bit, counters included (call startSpan() again
  // before evaluate() afterwards). The engines' path: chosen per primitive (load) — its kind,
  // and 64-bit host registers for the b and c accumulators, b, c, √Δ and the depth unit where
  // the configuration's widths and the primitive's coefficients and exponents provably fit
  // them (fits64, pixel_datapath.cpp) — so the inner loop tests neither; tests check it
  // against evaluate() (tests/hw_model/test_pixel_datapath_fast.cpp).
  void evaluateSpan(int u, int v, int n, PixelOutcome* out, OverflowCounters& ovf) {
    (this->*evalSpan_)(u, v, n, out, ovf);
  }
  // Whether evaluateSpan runs this primitive in 64-bit host registers (for tests).
  bool narrowHostPath() const { return narrow_; }
  // The loaded primitive's passes through the clip unit, the same at every pixel (every
  // PixelOutcome::clipPasses): one per clip_evaluators planes, plus one for a solid's caps.
  int clipPasses() const { return clipPasses_; }
  // The same for primitive `s` under `cfg`, without loading it.
  static int clipPassesOf(const PrimitiveSetup& s, const HwConfig& cfg);
  // For a solid quadric (not a facet): {f <= 0} ∩ clip polyhedron ∩ [0, 1] at the current
  // position as up to 2 intervals of positive length, ascending — what a CSG method needs
  // of each operand; the fixed-point form of raster/pixel/solid_intervals.h, from the same
  // interpolators, square root and depth unit as evaluate() (pixel_datapath_intervals.cpp).
  int solidIntervals(OverflowCounters& ovf, FixedDepthInterval out[2]);

 private:
  // The primitive's kind as a template constant of the host paths; Any reads it per pixel.
  enum class Shape { Any, Facet, Surface, Solid };
  // evaluate() for the configured rounding mode R and depth variant V, chosen once per
  // primitive (evalFloored_ and evalSpan_): the per-pixel path tests neither. T is the host
  // register type of b, c, √Δ and the depth unit (i128, or std::int64_t where it fits).
  template <Rounding R, DepthVariant V, Shape S, typename T>
  PixelOutcome evaluateFloored(OverflowCounters& ovf);
  template <Rounding R, DepthVariant V, Shape S, typename T>
  PixelOutcome evaluateUnfloored(OverflowCounters& ovf);
  template <Rounding R, DepthVariant V, Shape S, typename T>
  void evaluateSpanT(int u, int v, int n, PixelOutcome* out, OverflowCounters& ovf);
  template <Shape S, typename T = i128>
  void startSpanT(int u, int v);
  template <Shape S, typename T = i128>
  void stepRightT();
  template <Rounding R, DepthVariant V>
  void choosePaths();
  using SpanFn = void (PixelDatapath::*)(int, int, int, PixelOutcome*, OverflowCounters&);
  PixelOutcome (PixelDatapath::*evalFloored_)(OverflowCounters&) = nullptr;
  SpanFn evalSpan_ = nullptr;
  bool narrow_ = false;
  int clipPasses_ = 1;
  double invAbsA_ = 0;  // 1 / |a| for the 64-bit host path's division by a (depthRootsT)
  // The 64-bit host path's b and c accumulators (b_ and c_ there, the same values; those two
  // are then not advanced: startSpan() again before evaluate() after an evaluateSpan()).
  std::int64_t b64_ = 0, bA64_ = 0, c64_ = 0, cStep64_ = 0, c2A64_ = 0;
  const PrimitiveSetup* s_ = nullptr;
  const HwConfig& cfg_;
  QuadraticInterpolator delta_, c_;
  LinearInterpolator b_, facetZ_;
  std::vector<LinearInterpolator> h_, zk_;
  std::vector<i128> hv_, zkv_;
  WidthRange hRange_, valueRange_, deltaRange_, accRange_;  // the widths every pixel narrows to
  i128 depthLo_ = 0, depthHi_ = 0;                             // the depth datapath's clamp
};

}  // namespace qacc
