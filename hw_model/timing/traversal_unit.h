// TraversalUnit: scanline traversal of a primitive's screen box (design §3.2 step 3): per
// row, the span(s) where the contour conic Δ >= 0 (datapath/span_solver.h; solved once per
// row in the pixel datapath pass, engines/pixel_trace.h), issuing only those pixels, to
// the P pipelines screen-interleaved: pipeline (x + y) mod P, up to P pixels per cycle,
// in span order, a new row starting on a new cycle.
#pragma once
#include <vector>

#include "hw_model/config/hw_config.h"
#include "hw_model/datapath/primitive_setup.h"
#include "hw_model/datapath/span_solver.h"
#include "hw_model/timing/channel.h"
#include "hw_model/timing/tokens.h"
#include "hw_model/timing/unit.h"

namespace qacc {

struct PixelTrace;

class TraversalUnit : public Unit {
 public:
  struct Params {
    int pipelines = 2;
    static Params from(const HwConfig& cfg) { return {cfg.pipelines}; }
    int pipelineOf(int x, int y) const { return (x + y) % pipelines; }
  };

  // The rows' spans come from the PixelTrace (the same span solver, run beforehand).
  TraversalUnit(const Params& p, const std::vector<PrimitiveSetup>& setups, const PixelTrace& trace,
                Channel<PrimitiveToken>& in, std::vector<Channel<PixelToken>*> out)
      : Unit("traversal"), p_(p), setups_(setups), trace_(trace), in_(in), out_(std::move(out)) {}
  bool tick(std::uint64_t now) override;
  bool holdsWork() const override { return prim_ >= 0; }

 private:
  bool nextRow();
  Params p_;
  const std::vector<PrimitiveSetup>& setups_;
  const PixelTrace& trace_;
  Channel<PrimitiveToken>& in_;
  std::vector<Channel<PixelToken>*> out_;
  int prim_ = -1;
  std::size_t row_ = 0;  // next row of the primitive's trace
  int y_ = 0;
  Span rowSpans_[2];
  int nSpans_ = 0, span_ = 0, x_ = 0, k_ = 0;
};

}  // namespace qacc
