#include "hw_model/timing/csg_list_unit.h"

#include <algorithm>
#include <limits>

namespace qacc {

bool CsgListUnit::tick(std::uint64_t now) {
  now_ = now;
  bool changed = false, stalled = false;
  for (std::size_t p = 0; p < in_.size(); ++p) {
    if (busyUntil_[p] > now || !in_[p]->ready()) continue;
    const CsgToken t = in_[p]->front();
    in_[p]->receive();
    changed = true;
    if (t.index < 0) {
      ++markers_[std::size_t(t.job)];
      continue;
    }
    const int n = jobs_[std::size_t(t.job)].issued[std::size_t(t.index)].intervals;
    busyUntil_[p] = now + std::uint64_t(std::max(1, n));
    countItem();
  }
  while (nextJob_ < jobs_.size() && jobs_[nextJob_].pruned) ++nextJob_;  // never issued
  if (nextJob_ < jobs_.size() && markers_[nextJob_] == int(in_.size())) {
    if (out_.canSend()) {
      out_.send(int(nextJob_++));
      changed = true;
    } else {
      stalled = true;
    }
  }
  if (changed) countBusy();
  else if (stalled) countStall();
  else if (holdsWork()) countBusy();
  else countIdle();
  return changed;
}

std::uint64_t CsgListUnit::nextEvent() const {
  std::uint64_t t = std::numeric_limits<std::uint64_t>::max();
  // A port's insertion done: it takes its next interval, or the unit's tick counts idle from
  // then on when no port is busy (holdsWork), whether or not an interval waits.
  for (std::size_t p = 0; p < in_.size(); ++p)
    if (busyUntil_[p] > now_) t = std::min(t, busyUntil_[p]);
  return t;
}

bool CsgListUnit::holdsWork() const {
  if (nextJob_ < jobs_.size() && markers_[nextJob_] == int(in_.size())) return true;
  for (std::uint64_t b : busyUntil_)
    if (b > now_) return true;
  return false;
}

}  // namespace qacc
