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
#include "hw_model/engines/pixel_trace.h"
#include "hw_model/timing/channel.h"
#include "hw_model/timing/tokens.h"
#include "hw_model/timing/unit.h"

namespace qacc {

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
                std::vector<std::uint32_t> storedFloors = {});
  bool tick(std::uint64_t now);
  bool holdsWork() const { return prim_ >= 0; }
  // Unchanged: stalled on a pipeline's full channel (a receive frees it) or waiting for a
  // primitive. With the hierarchical Z unit a lookup may happen in any cycle: at once.
  std::uint64_t nextChange(std::uint64_t now) const {
    if (hiz_) return now;
    return prim_ >= 0 ? kNoEvent : in_.arrivalFrom(now);
  }

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
  int hizTile_ = 0;  // the hierarchical Z unit's tile size (0: no unit)
  std::vector<std::uint32_t> floors_;
  bool blockChecked_ = false, primTested_ = false, primAccepted_ = false;
};

inline bool TraversalUnit::nextRow() {
  const std::vector<RowSpans>& rows = trace_.rows[std::size_t(prim_)];
  if (row_ >= rows.size()) return false;
  const RowSpans& r = rows[row_++];
  y_ = r.y;
  nSpans_ = r.n;
  rowSpans_[0] = r.s[0];
  rowSpans_[1] = r.s[1];
  span_ = 0;
  x_ = rowSpans_[0].x0;
  blockChecked_ = false;
  return true;
}

inline bool TraversalUnit::tick(std::uint64_t now) {
  (void)now;
  bool changed = false;
  if (prim_ < 0 && in_.ready()) {
    prim_ = in_.front();
    trace_.awaitPrimitive(prim_);  // the host's wait for its pixels, when filled ahead (no modeled cycle)
    in_.receive();
    countItem();
    changed = true;
    const PrimitiveSetup& s = setups_[std::size_t(prim_)];
    row_ = 0;
    k_ = 0;
    primTested_ = primAccepted_ = false;
    if (!s.visible || !nextRow()) endPrimitive();
    countBusy();
    return changed;  // the first pixels leave next cycle (span solve)
  }
  if (prim_ < 0) {
    countIdle();
    return changed;
  }
  // Issue up to one pixel per pipeline, in span order, stopping at the first pipeline
  // whose channel is full (pixels stay in order).
  std::uint64_t used = 0;  // pipelines already fed this cycle (P <= 64)
  bool stalled = false;
  while (prim_ >= 0) {
    if (hiz_ && !blockChecked_ && rejectBlock(now)) {
      changed = true;
      break;  // the lookup of a rejected block ends the cycle
    }
    const int p = p_.pipelineOf(x_, y_);
    if (used & (std::uint64_t(1) << p)) break;
    Channel<PixelToken>& out = *out_[std::size_t(p)];
    if (!out.canSend()) {
      stalled = true;
      break;
    }
    out.send({prim_, x_, y_, k_++});
    used |= std::uint64_t(1) << p;
    changed = true;
    if (++x_ >= rowSpans_[span_].x1) {
      blockChecked_ = false;
      if (++span_ < nSpans_) {
        x_ = rowSpans_[span_].x0;
      } else {
        if (!nextRow()) endPrimitive();
        break;  // a new row starts next cycle
      }
    } else if (hiz_ && x_ % hizTile_ == 0) {
      blockChecked_ = false;  // the next block begins
    }
  }
  if (changed) countBusy();
  else if (stalled) countStall();
  else countIdle();
  return changed;
}

}  // namespace qacc
