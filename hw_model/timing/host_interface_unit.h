// HostInterfaceUnit: the primitive descriptors (10 coefficients + 4 words per clip plane +
// material/object/flags) arrive in scene order over a bus of bus_width_bits, one transfer
// every bus_cycles_per_word cycles; a descriptor goes to the setup channel once complete.
#pragma once
#include <vector>

#include "hw_model/config/hw_config.h"
#include "hw_model/datapath/primitive_setup.h"
#include "hw_model/timing/channel.h"
#include "hw_model/timing/tokens.h"
#include "hw_model/timing/unit.h"

namespace qacc {

class HostInterfaceUnit final : public Unit {
 public:
  struct Params {
    int bus_width_bits = 32;
    int bus_cycles_per_word = 1;
    int descriptor_word_bits = 32;
    static Params from(const HwConfig& cfg) {
      return {cfg.bus_width_bits, cfg.bus_cycles_per_word, cfg.descriptor_word_bits};
    }
    // Cycles to transfer a descriptor of `words` words.
    int transferCycles(int words) const {
      const long long bits = (long long)words * descriptor_word_bits;
      return int((bits + bus_width_bits - 1) / bus_width_bits) * bus_cycles_per_word;
    }
  };

  HostInterfaceUnit(const Params& p, const std::vector<PrimitiveSetup>& setups, Channel<PrimitiveToken>& out)
      : Unit("host_interface"), p_(p), setups_(setups), out_(out) {}
  bool tick(std::uint64_t now);
  std::uint64_t nextEvent() const { return busy_ ? readyAt_ : kNoEvent; }
  // Unchanged: transferring until readyAt_, or stalled on a full channel (a receive frees it),
  // or done.
  std::uint64_t nextChange(std::uint64_t now) const { return busy_ && readyAt_ >= now ? readyAt_ : kNoEvent; }
  bool holdsWork() const { return next_ < int(setups_.size()) || busy_; }

 private:
  Params p_;
  const std::vector<PrimitiveSetup>& setups_;
  Channel<PrimitiveToken>& out_;
  int next_ = 0;
  bool busy_ = false;
  std::uint64_t readyAt_ = 0;
};

inline bool HostInterfaceUnit::tick(std::uint64_t now) {
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
