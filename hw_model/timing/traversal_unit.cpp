#include "hw_model/timing/traversal_unit.h"

#include <algorithm>

#include "hw_model/timing/hierarchical_z_unit.h"

namespace qacc {

TraversalUnit::TraversalUnit(const Params& p, const std::vector<PrimitiveSetup>& setups, const PixelTrace& trace,
                             Channel<PrimitiveToken>& in, std::vector<Channel<PixelToken>*> out,
                             HierarchicalZUnit* hiz, std::vector<std::uint32_t> storedFloors)
    : Unit("traversal"), p_(p), setups_(setups), trace_(trace), in_(in), out_(std::move(out)), hiz_(hiz),
      hizTile_(hiz ? hiz->params().tile_size : 0), floors_(std::move(storedFloors)) {}

void TraversalUnit::endPrimitive() {
  if (hiz_) hiz_->counters.primitiveDone(primTested_, primAccepted_);
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
  hiz_->counters.blockRejected(n, p_.pipelines, hiz_->params().lookup_cycles);
  k_ += n;
  x_ = end;
  blockChecked_ = false;
  if (x_ >= rowSpans_[span_].x1) {
    if (++span_ < nSpans_) x_ = rowSpans_[span_].x0;
    else if (!nextRow()) endPrimitive();
  }
  return true;
}

}  // namespace qacc
