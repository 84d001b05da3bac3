// SetupUnit: the timing of the setup processor (design §3.2 step 2). The arithmetic is
// datapath/setup_arithmetic.h, computed for every primitive before the timing loop; the
// unit takes primitives from the host interface one at a time, holds each for its
// multiply-add count on `setup_mad_units` units, then hands it to traversal. A primitive
// culled at the host (PrimitiveSetup::culled: its exact screen box misses the screen or the
// depth range) holds the unit for the box test's operations only and is dropped there:
// traversal never sees it (`culled()` counts them).
#pragma once
#include <algorithm>
#include <vector>

#include "hw_model/config/hw_config.h"
#include "hw_model/datapath/primitive_setup.h"
#include "hw_model/timing/channel.h"
#include "hw_model/timing/tokens.h"
#include "hw_model/timing/unit.h"

namespace qacc {

class SetupUnit final : public Unit {
 public:
  struct Params {
    int mad_units = 4;
    static Params from(const HwConfig& cfg) { return {cfg.setup_mad_units}; }
    // Cycles the setup of `s` occupies the unit (at least one).
    int cycles(const PrimitiveSetup& s) const {
      const int ops = s.culled ? s.boxTestOps : s.setupOps;
      return std::max(1, (ops + mad_units - 1) / mad_units);
    }
  };

  SetupUnit(const Params& p, const std::vector<PrimitiveSetup>& setups, Channel<PrimitiveToken>& in,
            Channel<PrimitiveToken>& out)
      : Unit("setup"), p_(p), setups_(setups), in_(in), out_(out) {}
  bool tick(std::uint64_t now);
  std::uint64_t nextEvent() const { return current_ >= 0 && readyAt_ > 0 ? readyAt_ : kNoEvent; }
  // Unchanged: computing until readyAt_, stalled on a full channel, or waiting for input.
  std::uint64_t nextChange(std::uint64_t now) const {
    if (current_ >= 0) return readyAt_ >= now ? readyAt_ : kNoEvent;
    return in_.arrivalFrom(now);
  }
  bool holdsWork() const { return current_ >= 0; }
  std::uint64_t culled() const { return culled_; }

 private:
  Params p_;
  const std::vector<PrimitiveSetup>& setups_;
  Channel<PrimitiveToken>& in_;
  Channel<PrimitiveToken>& out_;
  int current_ = -1;
  std::uint64_t readyAt_ = 0;
  std::uint64_t culled_ = 0;
};

inline bool SetupUnit::tick(std::uint64_t now) {
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
