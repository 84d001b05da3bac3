#include "hw_model/timing/pixel_pipeline_unit.h"

#include <algorithm>

namespace qacc {

bool PixelPipelineUnit::tick(std::uint64_t now) {
  bool changed = false, stalled = false;
  while (!inflight_.empty() && inflight_.front().ready <= now) {
    InFlight& f = inflight_.front();
    if (f.hit) {
      if (!out_.canPush()) {
        stalled = true;
        break;
      }
      out_.push(f.req);
    }
    inflight_.pop_front();
    changed = true;
  }
  if (now >= nextAccept_ && !in_.empty()) {
    const PixelToken t = in_.front();
    in_.pop();
    const TracedPixel& o = trace_.prims[std::size_t(t.prim)][std::size_t(t.k)];
    ++px_.tested;
    px_.clip_passes += std::uint64_t(o.clipPasses);
    if (o.hit) {
      if (zb_) __builtin_prefetch(&zb_->px[std::size_t(t.y) * std::size_t(zb_->width) + std::size_t(t.x)]);
      ++px_.covered;
      px_.caps += o.cap >= 0;
    } else {
      px_.clipped += o.candidate != 0;
    }
    inflight_.push_back({now + latency_, o.hit != 0, {t.prim, t.x, t.y, o.cap, o.z}});
    nextAccept_ = now + std::uint64_t(std::max(1, int(o.clipPasses)));
    countItem();
    changed = true;
  }
  if (stalled && !changed) countStall();
  else if (changed || !inflight_.empty()) countBusy();
  else countIdle();
  return changed;
}

std::uint64_t PixelPipelineUnit::nextEvent() const {
  std::uint64_t t = inflight_.empty() ? Unit::nextEvent() : inflight_.front().ready;
  if (!in_.empty()) t = std::min(t, nextAccept_);
  return t;
}

}  // namespace qacc
