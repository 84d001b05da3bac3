#include "hw_model/engines/machine_run.h"

#include <algorithm>
#include <limits>
#include <stdexcept>
#include <string>

namespace qacc {

std::uint64_t runMachine(ChannelRegistry& wires, std::vector<std::unique_ptr<Unit>>& units,
                         std::uint64_t& fastForwarded) {
  // The frame ends with the first cycle after which no unit holds work and every FIFO is
  // empty. That state can only be entered by a cycle where something changed, and the
  // cycle after it changes nothing, so the check runs only on unchanged cycles: ending
  // there, the frame took one cycle less than the loop ran.
  std::uint64_t quiet = 0;
  bool prevChanged = false;
  for (;;) {
    bool changed = false;
    const std::uint64_t now = wires.now();
    for (auto& u : units) changed |= u->tick(now);
    changed |= wires.endCycle();
    if (changed) {
      quiet = 0;
      prevChanged = true;
      continue;
    }
    bool working = !wires.idle();
    for (auto& u : units) working |= u->holdsWork();
    if (!working) {
      if (prevChanged) {  // the idle cycle the loop ran past the end is not part of the frame
        wires.retractCycle();
        for (auto& u : units) u->retractIdle();
      }
      break;
    }
    prevChanged = false;
    // Nothing moved: jump to the next timed event.
    std::uint64_t next = std::numeric_limits<std::uint64_t>::max();
    for (auto& u : units) next = std::min(next, u->nextEvent());
    if (next == std::numeric_limits<std::uint64_t>::max() || ++quiet > 1000000)
      throw std::runtime_error("hw-cycle: the pipeline deadlocked at cycle " + std::to_string(wires.now()));
    if (next > wires.now()) {
      const std::uint64_t skip = next - wires.now();
      for (auto& u : units) u->skip(skip);
      fastForwarded += skip;
      wires.skipTo(next);
    }
  }
  return wires.now();
}

}  // namespace qacc
