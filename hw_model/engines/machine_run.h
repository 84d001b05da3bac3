// runMachine: the clock of hw-cycle. Ticks wired timed units (timing/unit.h) cycle by
// cycle until no unit holds work and every channel is empty, jumping over cycles where
// nothing moves to the next timed event (fast-forward). The units are passed by their
// concrete types, so every tick is a direct call the compiler can inline into the loop.
#pragma once
#include <cstdint>
#include <optional>
#include <vector>

#include "hw_model/report/hw_stats.h"
#include "hw_model/timing/channel_registry.h"
#include "hw_model/timing/unit.h"

namespace qacc {

namespace machine_run_detail {
// A group of the wiring: one unit, the units of one type in a std::vector (in order), or
// an optional unit.
template <typename U, typename F>
void each(U& u, F& f) {
  f(u);
}
template <typename U, typename A, typename F>
void each(std::vector<U, A>& units, F& f) {
  for (U& u : units) f(u);
}
template <typename U, typename F>
void each(std::optional<U>& u, F& f) {
  if (u) f(*u);
}
[[noreturn]] void throwDeadlock(std::uint64_t now);
}  // namespace machine_run_detail

// Calls f on every unit of the groups, in the order given.
template <typename F, typename... Groups>
void forEachUnit(F&& f, Groups&... groups) {
  (machine_run_detail::each(groups, f), ...);
}

// Ticks the units of `groups` (each a unit, a std::vector of units or a std::optional unit)
// in the order given, every cycle. Returns the cycles the machine ran (wires.now() at the
// end); adds the cycles skipped by fast-forward to `fastForwarded`. Throws
// std::runtime_error on a deadlock.
template <typename... Groups>
std::uint64_t runMachine(ChannelRegistry& wires, std::uint64_t& fastForwarded, Groups&... groups) {
  // The frame ends with the first cycle after which no unit holds work and every FIFO is
  // empty. That state can only be entered by a cycle where something changed, and the
  // cycle after it changes nothing, so the check runs only on unchanged cycles: ending
  // there, the frame took one cycle less than the loop ran.
  std::uint64_t quiet = 0;
  bool prevChanged = false;
  for (;;) {
    bool changed = false;
    const std::uint64_t now = wires.now();
    forEachUnit([&](auto& u) { changed |= u.tick(now); }, groups...);
    changed |= wires.endCycle();
    if (changed) {
      quiet = 0;
      prevChanged = true;
      continue;
    }
    bool working = !wires.idle();
    forEachUnit([&](auto& u) { working |= u.holdsWork(); }, groups...);
    if (!working) {
      if (prevChanged) {  // the idle cycle the loop ran past the end is not part of the frame
        wires.retractCycle();
        forEachUnit([](auto& u) { u.retractIdle(); }, groups...);
      }
      break;
    }
    prevChanged = false;
    // Nothing moved: jump to the next timed event.
    std::uint64_t next = Unit::kNoEvent;
    forEachUnit(
        [&](auto& u) {
          const std::uint64_t t = u.nextEvent();
          if (t < next) next = t;
        },
        groups...);
    if (next == Unit::kNoEvent || ++quiet > 1000000) machine_run_detail::throwDeadlock(wires.now());
    if (next > wires.now()) {
      const std::uint64_t skip = next - wires.now();
      forEachUnit([&](auto& u) { u.skip(skip, u.holdsWork()); }, groups...);
      fastForwarded += skip;
      wires.skipTo(next);
    }
  }
  return wires.now();
}

// Appends every unit's counters to `out`, in the order given.
template <typename... Groups>
void appendUnitStats(std::vector<UnitStats>& out, Groups&... groups) {
  forEachUnit([&](auto& u) { out.push_back(u.stats()); }, groups...);
}

}  // namespace qacc
