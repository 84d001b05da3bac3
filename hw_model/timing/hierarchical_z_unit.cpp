#include "hw_model/timing/hierarchical_z_unit.h"

namespace qacc {

bool HierarchicalZUnit::rejects(std::uint64_t now, int x, int y, std::uint32_t storedFloor) {
  applyDue(now);
  lastActive_ = now;
  countItem();
  ++counters.blocks_tested;
  return memory_.rejects(memory_.tileOf(x, y), storedFloor);
}

}  // namespace qacc
