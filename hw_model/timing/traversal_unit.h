// TraversalUnit: scanline traversal of a primitive's screen box (design §3.2 step 3): per
// row, the span(s) where the contour conic Δ >= 0 (datapath/span_solver.h; solved once per
// row in the pixel datapath pass, engines/pixel_trace.h), issuing only those pixels, to
// the P pipelines screen-interleaved: pipeline (x + y) mod P, up to P pixels per cycle,
// in span order, a new row starting on a new cycle. With the hierarchical Z unit
// (timing/hierarchical_z_unit.h), each block of a span (its pixels in one hiz_tile_size²
// tile) is looked up first: a rejected block is skipped (its lookup ends the cycle), an
// accepted one is issued as before.
#pragma once
#include <vector>

#include "hw_model/config/hw_config.h"
#include "hw_model/datapath/primitive_setup.h"
#include "hw_model/datapath/screen_interleave.h"
#include "hw_model/datapath/span_solver.h"
#include "hw_model/timing/channel.h"
#include "hw_model/timing/tokens.h"
#include "hw_model/timing/unit.h"

namespace qacc {

struct PixelTrace;
class HierarchicalZUnit;

class TraversalUnit final : public Unit {
 public:
  struct Params {
    int pipelines = 2;
    static Params from(const HwConfig& cfg) { return {cfg.pipelines}; }
    int pipelineOf(int x, int y) const { return interleavedUnit(x, y, pipelines); }
  };

  // The rows' spans come from the PixelTrace (the same span solver, run beforehand).
  // `hiz` (optional): the hierarchical Z unit, with each primitive's stored depth floor
  // (ZBufferMemory::storedValue of PrimitiveSetup::zFloor) in `storedFloors`.
  TraversalUnit(const Params& p, const std::vector<PrimitiveSetup>& setups, const PixelTrace& trace,
                Channel<PrimitiveToken>& in, std::vector<Channel<PixelToken>*> out, HierarchicalZUnit* hiz = nullptr,
                std::vector<std::uint32_t> storedFloors = {})
      : Unit("traversal"), p_(p), setups_(setups), trace_(trace), in_(in), out_(std::move(out)), hiz_(hiz),
        floors_(std::move(storedFloors)) {}
  bool tick(std::uint64_t now) override;
  bool holdsWork() const override { return prim_ >= 0; }

 private:
  bool nextRow();
  void endPrimitive();
  // The hierarchical Z lookup of the block starting at x_: true when it was rejected (skipped).
  bool rejectBlock(std::uint64_t now);
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
  HierarchicalZUnit* hiz_;
  std::vector<std::uint32_t> floors_;
  bool blockChecked_ = false, primTested_ = false, primAccepted_ = false;
};

}  // namespace qacc
