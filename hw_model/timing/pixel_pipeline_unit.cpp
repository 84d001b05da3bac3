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
    const int passes = trace_.clipPasses(t.prim);
    ++px_.tested;
    px_.clip_passes += std::uint64_t(passes);
    if (o.hit) {
      if (zb_) __builtin_prefetch(&zb_->px[zb_->index(t.x, t.y)]);
      ++px_.covered;
      px_.caps += o.cap >= 0;
    } else {
      px_.clipped += o.candidate != 0;
    }
    stages_.accept({o.hit, {t.prim, t.x, t.y, int(o.cap), std::int64_t(o.z)}}, std::uint64_t(std::max(1, passes)));
    countItem();
    changed = true;
  }
  countCycle(changed, stalled, stages_.holdsWork());
  return changed;
}

}  // namespace qacc
