#include "hw_model/timing/pixel_pipeline_unit.h"

#include <algorithm>

namespace qacc {

bool PixelPipelineUnit::tick(std::uint64_t now) {
  (void)now;
  bool changed = false, stalled = false;
  while (stages_.done()) {
    const InFlight& f = stages_.front();
    if (f.hit) {
      if (!out_.canSend()) {
        stalled = true;
        break;
      }
      out_.send(f.point);
    }
    stages_.retire();
    changed = true;
  }
  if (stages_.canAccept() && in_.ready()) {
    const PixelToken t = in_.front();
    in_.receive();
    const TracedPixel& o = trace_.pixel(t.prim, t.k);
    ++px_.tested;
    px_.clip_passes += std::uint64_t(o.clipPasses);
    if (o.hit) {
      if (zb_) __builtin_prefetch(&zb_->px[zb_->index(t.x, t.y)]);
      ++px_.covered;
      px_.caps += o.cap >= 0;
    } else {
      px_.clipped += o.candidate != 0;
    }
    stages_.accept({o.hit != 0, {t.prim, t.x, t.y, o.cap, o.z}}, std::uint64_t(std::max(1, int(o.clipPasses))));
    countItem();
    changed = true;
  }
  countCycle(changed, stalled, stages_.holdsWork());
  return changed;
}

}  // namespace qacc
