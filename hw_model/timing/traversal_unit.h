// TraversalUnit: scanline traversal of a primitive's screen box (design §3.2 step 3).
// Per scanline it solves the contour conic Δ(u, v) = 0 for the span(s) where Δ >= 0 (at
// most two: a hyperbola's row can have two pieces), widened by one pixel against the
// quantisation of Δ, and issues only those pixels (pixels tested); the pixel pipelines
// then decide coverage exactly from the interpolated Δ. Caps of solids (a <= 0) and
// facets can show where Δ < 0: their rows are issued whole. Pixels go to the P
// pipelines screen-interleaved: pipeline (x + y) mod P, up to P pixels per cycle.
// spans() is the arithmetic; the cycle engine solves every row once in the pixel
// datapath pass (pixel_trace.h) and the timed unit walks those rows.
#pragma once
#include <vector>

#include "hw_model/timing/fifo.h"
#include "hw_model/datapath/primitive_setup.h"
#include "hw_model/timing/unit.h"

namespace qacc {

struct Span {
  int x0 = 0, x1 = 0;  // [x0, x1) in screen pixels
};

struct PixelToken {
  int prim = 0;
  int x = 0, y = 0;
  int k = 0;  // issue order within the primitive: its entry in the PixelTrace
};

struct PixelTrace;

class TraversalUnit : public Unit {
 public:
  // Spans of row y (screen) restricted to [xlo, xhi); returns their number (0..2).
  static int spans(const PrimitiveSetup& s, int y, int xlo, int xhi, Span out[2]);
  static int pipelineOf(int x, int y, int P) { return (x + y) % P; }

  // The rows' spans come from the PixelTrace (the same spans(), solved beforehand).
  TraversalUnit(const std::vector<PrimitiveSetup>& setups, const PixelTrace& trace, Fifo<int>& in,
                std::vector<Fifo<PixelToken>>& out)
      : Unit("traversal"), setups_(setups), trace_(trace), in_(in), out_(out) {}
  bool tick(std::uint64_t now) override;
  bool holdsWork() const override { return prim_ >= 0; }

 private:
  bool nextRow();
  const std::vector<PrimitiveSetup>& setups_;
  const PixelTrace& trace_;
  Fifo<int>& in_;
  std::vector<Fifo<PixelToken>>& out_;
  int prim_ = -1;
  std::size_t row_ = 0;  // next row of the primitive's trace
  int y_ = 0;
  Span rowSpans_[2];
  int nSpans_ = 0, span_ = 0, x_ = 0, k_ = 0;
};

}  // namespace qacc
