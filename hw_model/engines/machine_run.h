// runMachine: the clock of hw-cycle. Ticks wired timed units (timing/unit.h) cycle by
// cycle until no unit holds work and every channel is empty, jumping over cycles where
// nothing moves to the next timed event (fast-forward).
#pragma once
#include <cstdint>
#include <memory>
#include <vector>

#include "hw_model/timing/channel_registry.h"
#include "hw_model/timing/unit.h"

namespace qacc {

// Returns the cycles the machine ran (wires.now() at the end); adds the cycles skipped
// by fast-forward to `fastForwarded`. Throws std::runtime_error on a deadlock.
std::uint64_t runMachine(ChannelRegistry& wires, std::vector<std::unique_ptr<Unit>>& units,
                         std::uint64_t& fastForwarded);

}  // namespace qacc
