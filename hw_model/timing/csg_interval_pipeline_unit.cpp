#include "hw_model/timing/csg_interval_pipeline_unit.h"

#include <algorithm>

namespace qacc {

bool CsgIntervalPipelineUnit::tick(std::uint64_t now) {
  (void)now;
  bool changed = false, stalled = false;
  while (stages_.done()) {
    if (!out_.canSend()) {
      stalled = true;
      break;
    }
    out_.send(stages_.front());
    stages_.retire();
    changed = true;
  }
  if (stages_.canAccept() && in_.ready()) {
    const CsgToken t = in_.front();
    in_.receive();
    int interval = 1;
    if (t.index >= 0) {
      interval = std::max(1, jobs_[std::size_t(t.job)].issued[std::size_t(t.index)].clipPasses);
      countItem();
    }
    stages_.accept(t, std::uint64_t(interval));
    changed = true;
  }
  countCycle(changed, stalled, stages_.holdsWork());
  return changed;
}

}  // namespace qacc
