#include "hw_model/pixel_pipeline_unit.h"

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
    if (t.prim != currentPrim_) {
      currentPrim_ = t.prim;
      pipe_ = std::make_unique<PixelPipeline>(setups_[std::size_t(t.prim)], cfg_);
    }
    const PrimitiveSetup& s = setups_[std::size_t(t.prim)];
    const PixelOutcome o = pipe_->evaluateAt(t.x - s.x0, t.y - s.y0, ovf_);
    ++px_.tested;
    px_.clip_passes += std::uint64_t(o.clipPasses);
    if (o.hit) {
      ++px_.covered;
      px_.caps += o.cap >= 0;
    } else {
      px_.clipped += o.candidate;
    }
    inflight_.push_back({now + latency_, o.hit, {t.prim, t.x, t.y, o.cap, o.z}});
    nextAccept_ = now + std::uint64_t(std::max(1, o.clipPasses));
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
