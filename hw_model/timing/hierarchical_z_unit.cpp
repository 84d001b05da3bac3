#include "hw_model/timing/hierarchical_z_unit.h"

namespace qacc {

void HierarchicalZUnit::applyDue(std::uint64_t now) {
  while (!pending_.empty() && pending_.front().due <= now) {
    const Update& u = pending_.front();
    memory_.write(u.x, u.y, u.stored);
    pending_.pop_front();
    lastActive_ = now;
  }
}

bool HierarchicalZUnit::rejects(std::uint64_t now, int x, int y, std::uint32_t storedFloor) {
  applyDue(now);
  lastActive_ = now;
  countItem();
  ++counters.blocks_tested;
  return memory_.rejects(memory_.tileOf(x, y), storedFloor);
}

bool HierarchicalZUnit::tick(std::uint64_t now) {
  applyDue(now);
  // Busy in a cycle with a lookup or a tile update (the traversal unit ticks first).
  if (lastActive_ == now) countBusy();
  else countIdle();
  return false;  // the tile memory's state moves no token
}

}  // namespace qacc
