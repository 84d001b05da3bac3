#include "hw_model/timing/host_interface_unit.h"

namespace qacc {

bool HostInterfaceUnit::tick(std::uint64_t now) {
  bool changed = false;
  if (!busy_ && next_ < int(setups_.size())) {
    busy_ = true;
    // The last word arrives transferCycles - 1 cycles after the first; the descriptor is
    // handed on in that cycle.
    readyAt_ = now + std::uint64_t(p_.transferCycles(setups_[std::size_t(next_)].descriptorWords)) - 1;
    changed = true;
  }
  if (busy_ && now >= readyAt_) {
    if (out_.canSend()) {
      out_.send(next_++);
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
