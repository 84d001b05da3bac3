#include "hw_model/timing/traversal_unit.h"

#include <algorithm>

#include "hw_model/engines/pixel_trace.h"
#include "hw_model/timing/hierarchical_z_unit.h"

namespace qacc {

void TraversalUnit::endPrimitive() {
  if (hiz_ && primTested_) {
    ++hiz_->counters.primitives_tested;
    hiz_->counters.primitives_rejected += !primAccepted_;
  }
  prim_ = -1;
}

bool TraversalUnit::rejectBlock(std::uint64_t now) {
  blockChecked_ = true;
  primTested_ = true;
  const int tile = hiz_->params().tile_size;
  const int end = std::min(rowSpans_[span_].x1, (x_ / tile + 1) * tile);
  if (!hiz_->rejects(now, x_, y_, floors_[std::size_t(prim_)])) {
    primAccepted_ = true;
    return false;
  }
  const int n = end - x_;
  HierarchicalZCounters& c = hiz_->counters;
  ++c.blocks_rejected;
  c.pixels_rejected += std::uint64_t(n);
  const int issueCycles = (n + p_.pipelines - 1) / p_.pipelines;
  if (issueCycles > hiz_->params().lookup_cycles) c.issue_cycles_saved += std::uint64_t(issueCycles - hiz_->params().lookup_cycles);
  k_ += n;
  x_ = end;
  blockChecked_ = false;
  if (x_ >= rowSpans_[span_].x1) {
    if (++span_ < nSpans_) x_ = rowSpans_[span_].x0;
    else if (!nextRow()) endPrimitive();
  }
  return true;
}

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
  blockChecked_ = false;
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
    } else if (hiz_ && x_ % hiz_->params().tile_size == 0) {
      blockChecked_ = false;  // the next block begins
    }
  }
  if (changed) countBusy();
  else if (stalled) countStall();
  else countIdle();
  return changed;
}

}  // namespace qacc
