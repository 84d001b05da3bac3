#include "hw_model/timing/traversal_unit.h"

#include "hw_model/engines/pixel_trace.h"

namespace qacc {

bool TraversalUnit::nextRow() {
  const std::vector<RowSpans>& rows = trace_.rows[std::size_t(prim_)];
  if (row_ >= rows.size()) return false;
  const RowSpans& r = rows[row_++];
  y_ = r.y;
  nSpans_ = r.n;
  rowSpans_[0] = r.s[0];
  rowSpans_[1] = r.s[1];
  span_ = 0;
  x_ = rowSpans_[0].x0;
  return true;
}

bool TraversalUnit::tick(std::uint64_t now) {
  (void)now;
  bool changed = false;
  if (prim_ < 0 && in_.ready()) {
    prim_ = in_.front();
    in_.receive();
    countItem();
    changed = true;
    const PrimitiveSetup& s = setups_[std::size_t(prim_)];
    row_ = 0;
    k_ = 0;
    if (!s.visible || !nextRow()) prim_ = -1;
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
      if (++span_ < nSpans_) {
        x_ = rowSpans_[span_].x0;
      } else {
        if (!nextRow()) prim_ = -1;
        break;  // a new row starts next cycle
      }
    }
  }
  if (changed) countBusy();
  else if (stalled) countStall();
  else countIdle();
  return changed;
}

}  // namespace qacc
