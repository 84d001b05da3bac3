#include "hw_model/timing/csg_issue_unit.h"

#include <limits>

namespace qacc {

bool CsgIssueUnit::tick(std::uint64_t now) {
  now_ = now;
  bool changed = false, stalled = false;
  while (freed_.ready()) {
    freed_.receive();
    ++free_;
    changed = true;
  }
  if (next_ < jobs_.size()) {
    const CsgJob& next = jobs_[next_];
    // The box tester works one job ahead: it starts on the next job while the current one
    // issues (its flags go to the second of two flag buffers).
    if (next.testCycles > 0 && testedJob_ != next_) {
      testedJob_ = next_;
      testDone_ = now + std::uint64_t(next.testCycles);
      changed = true;
    }
    const bool tested = next.testCycles == 0 || now >= testDone_;
    if (!tested) {
      // the job waits for its tests
    } else if (next.pruned) {  // empty in its tile: done after the tests, the tester moves on
      ++next_;
      countItem();
      changed = true;
    } else if (job_ < 0 && free_ > 0) {
      job_ = int(next_++);
      --free_;
      k_ = 0;
      markers_ = 0;
      countItem();
      changed = true;
    }
  }
  if (job_ >= 0) {
    const std::vector<CsgLeafPixel>& px = jobs_[std::size_t(job_)].issued;
    const std::size_t P = out_.size();
    std::uint64_t used = 0;  // pipelines already fed this cycle (P <= 64)
    while (k_ < px.size()) {
      if (used && px[k_].y != px[k_ - 1].y) break;  // a new row starts on a new cycle
      const int p = p_.pipelineOf(px[k_].x, px[k_].y);
      if (used & (std::uint64_t(1) << p)) break;
      if (!out_[std::size_t(p)]->canSend()) {
        stalled = true;
        break;
      }
      out_[std::size_t(p)]->send({job_, int(k_++)});
      used |= std::uint64_t(1) << p;
      changed = true;
    }
    if (k_ == px.size()) {
      for (std::size_t p = 0; p < P; ++p) {
        const std::uint64_t bit = std::uint64_t(1) << p;
        if ((markers_ & bit) || (used & bit)) continue;
        if (!out_[p]->canSend()) {
          stalled = true;
          continue;
        }
        out_[p]->send({job_, -1});
        markers_ |= bit;
        changed = true;
      }
      if (markers_ == (P == 64 ? ~std::uint64_t(0) : (std::uint64_t(1) << P) - 1)) job_ = -1;
    }
  }
  if (changed || testing()) countBusy();
  else if (stalled || holdsWork()) countStall();  // waiting for a channel or a free list buffer
  else countIdle();
  return changed;
}

std::uint64_t CsgIssueUnit::nextEvent() const {
  return testing() ? testDone_ : std::numeric_limits<std::uint64_t>::max();
}

}  // namespace qacc
