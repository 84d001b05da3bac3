// ChannelRegistry: the clock of the cycle engine and every channel of the machine. Units
// are wired in one place (engines/cycle_engine.cpp) with channels the registry makes; each
// channel keeps its own two-phase state (channel.h: the tick order of the units within a
// cycle does not matter) and counts its moves here, so endCycle() only advances the clock
// and says whether anything moved; idle() says whether anything is still on a wire.
#pragma once
#include <cstddef>
#include <cstdint>
#include <memory>
#include <vector>

#include "hw_model/timing/channel.h"

namespace qacc {

class ChannelRegistry {
 public:
  std::uint64_t now() const { return now_; }
  // The clock itself, for what reads it every cycle (channels, a unit's pipeline stages).
  const std::uint64_t& clock() const { return now_; }
  // Capacity 0: unbounded.
  template <typename T>
  Channel<T>& make(std::size_t capacity) {
    auto c = std::make_unique<Channel<T>>(now_, capacity, moves_);
    Channel<T>& ref = *c;
    channels_.push_back(std::move(c));
    return ref;
  }
  // End of the cycle: the clock advances. True when anything was sent or received during
  // the cycle.
  bool endCycle() {
    const bool changed = moves_ != 0;
    moves_ = 0;
    ++now_;
    return changed;
  }
  // Fast-forward (nothing is sent or received in the skipped cycles).
  void skipTo(std::uint64_t cycle) { now_ = cycle; }
  // Takes back the last cycle (the engine ran one idle cycle past the end of the frame).
  void retractCycle() { --now_; }
  // Nothing on any wire.
  bool idle() const {
    for (const auto& c : channels_)
      if (!c->idle()) return false;
    return true;
  }

 private:
  std::uint64_t now_ = 0;
  std::vector<std::unique_ptr<ChannelBase>> channels_;
  std::uint64_t moves_ = 0;  // sends and receives in the current cycle
};

}  // namespace qacc
