#include "hw_model/timing/host_interface_unit.h"

namespace qacc {

bool HostInterface::tick(std::uint64_t now) {
  bool changed = false;
  if (!busy_ && next_ < int(setups_.size())) {
    busy_ = true;
    readyAt_ = now + std::uint64_t(transferCycles(setups_[std::size_t(next_)].descriptorWords, cfg_)) - 1;
    changed = true;
  }
  if (busy_ && now >= readyAt_) {
    if (out_.canPush()) {
      out_.push(next_++);
      busy_ = false;
      countItem();
      changed = true;
    } else {
      countStall();
      return changed;
    }
  }
  if (busy_ || changed) countBusy();
  else countIdle();
  return changed;
}

}  // namespace qacc
