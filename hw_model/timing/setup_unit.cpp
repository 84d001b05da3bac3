#include "hw_model/timing/setup_unit.h"

namespace qacc {

bool SetupUnit::tick(std::uint64_t now) {
  bool changed = false;
  if (current_ >= 0 && now >= readyAt_) {
    if (setups_[std::size_t(current_)].culled) {  // dropped after the box test
      current_ = -1;
      ++culled_;
      changed = true;
    } else if (out_.canSend()) {
      out_.send(current_);
      current_ = -1;
      changed = true;
    } else {
      countStall();
      return false;
    }
  }
  if (current_ < 0 && in_.ready()) {
    current_ = in_.front();
    in_.receive();
    readyAt_ = now + std::uint64_t(p_.cycles(setups_[std::size_t(current_)]));
    countItem();
    changed = true;
  }
  if (current_ >= 0 || changed) countBusy();
  else countIdle();
  return changed;
}

}  // namespace qacc
