#include "hw_model/timing/csg_sweep_unit.h"

#include <algorithm>
#include <limits>

namespace qacc {

bool CsgSweepUnit::tick(std::uint64_t now) {
  bool changed = false, stalled = false;
  const std::size_t P = out_.size();
  if (job_ < 0 && in_.ready()) {
    job_ = in_.front();
    in_.receive();
    const std::vector<CsgSweptPixel>& sw = jobs_[std::size_t(job_)].swept;
    for (auto& q : queue_) q.clear();
    for (std::size_t i = 0; i < sw.size(); ++i) queue_[std::size_t(p_.pipelineOf(sw[i].x, sw[i].y))].push_back(int(i));
    std::fill(pos_.begin(), pos_.end(), 0);
    changed = true;
  }
  if (job_ < 0) {
    countIdle();
    return changed;
  }
  const std::vector<CsgSweptPixel>& sw = jobs_[std::size_t(job_)].swept;
  bool finished = true;
  for (std::size_t p = 0; p < P; ++p) {
    if (current_[p] >= 0 && doneAt_[p] <= now) {
      const CsgSweptPixel& s = sw[std::size_t(current_[p])];
      if (s.prim >= 0) {
        if (!out_[p]->canSend()) {
          stalled = true;
          finished = false;
          continue;
        }
        out_[p]->send({s.prim, s.x, s.y, s.cap, std::int64_t(s.z)});
      }
      current_[p] = -1;
      changed = true;
    }
    if (current_[p] < 0 && pos_[p] < queue_[p].size()) {
      current_[p] = queue_[p][pos_[p]++];
      doneAt_[p] = now + std::uint64_t(std::max(1, sw[std::size_t(current_[p])].ends));
      countItem();
      changed = true;
    }
    finished &= current_[p] < 0 && pos_[p] == queue_[p].size();
  }
  if (finished) {
    if (freed_.canSend()) {
      freed_.send(job_);
      job_ = -1;
      changed = true;
    } else {
      stalled = true;
    }
  }
  if (changed) countBusy();
  else if (stalled) countStall();
  else countBusy();  // sweeping
  return changed;
}

std::uint64_t CsgSweepUnit::nextEvent() const {
  std::uint64_t t = std::numeric_limits<std::uint64_t>::max();
  if (job_ < 0) return t;
  for (std::size_t p = 0; p < out_.size(); ++p)
    if (current_[p] >= 0) t = std::min(t, doneAt_[p]);
  return t;
}

}  // namespace qacc
