// HostInterface: the primitive descriptors (10 coefficients + 4 words per clip plane +
// material/object/flags) arrive in scene order over a bus of bus_width_bits, one transfer
// every bus_cycles_per_word cycles; a descriptor goes to the setup FIFO once complete.
#pragma once
#include <vector>

#include "hw_model/timing/fifo.h"
#include "hw_model/config/hw_config.h"
#include "hw_model/datapath/primitive_setup.h"
#include "hw_model/timing/unit.h"

namespace qacc {

class HostInterface : public Unit {
 public:
  static int transferCycles(int descriptorWords, const HwConfig& cfg) {
    const long long bits = (long long)descriptorWords * cfg.descriptor_word_bits;
    return int((bits + cfg.bus_width_bits - 1) / cfg.bus_width_bits) * cfg.bus_cycles_per_word;
  }
  HostInterface(const std::vector<PrimitiveSetup>& setups, const HwConfig& cfg, Fifo<int>& out)
      : Unit("host_interface"), setups_(setups), cfg_(cfg), out_(out) {}
  bool tick(std::uint64_t now) override;
  std::uint64_t nextEvent() const override { return busy_ ? readyAt_ : Unit::nextEvent(); }
  bool holdsWork() const override { return next_ < int(setups_.size()) || busy_; }

 private:
  const std::vector<PrimitiveSetup>& setups_;
  const HwConfig& cfg_;
  Fifo<int>& out_;
  int next_ = 0;
  bool busy_ = false;
  std::uint64_t readyAt_ = 0;
};

}  // namespace qacc
