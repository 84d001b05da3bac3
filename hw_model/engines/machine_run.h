// runMachine: the clock of hw-cycle. Ticks wired timed units (timing/unit.h) cycle by
// cycle until no unit holds work and every channel is empty. The units are passed by their
// concrete types, so every tick is a direct call the compiler can inline into the loop.
//
// Every cycle is counted as ticking it counts (busy, stall, idle per unit; the Z unit's
// conflicts and round-robin pointer), but not every cycle is ticked. After a cycle where
// nothing moved, the clock ticks the next cycle as usual while noting every unit's counters
// before and after, and adds that tick's counts once for each further cycle in which no tick
// may differ from it (Unit::repeatTick):
//  - fast-forward: up to the next timed event of any unit (Unit::nextEvent: an item
//    finishing, a transfer or a setup done, a bank freed); nothing moves before it;
//  - stalled cycles: where some unit waits without a timed event of its own (on a full
//    channel: the host on setup, traversal on the pipelines), up to the first cycle at which
//    any unit's tick may differ (Unit::nextChange).
// A unit that changes in a cycle the clock repeats is a logic error (thrown). Tests compare
// every counter with the clock that ticks each cycle (MachineClock::EveryCycle).
#pragma once
#include <algorithm>
#include <cstdint>
#include <optional>
#include <vector>

#include "hw_model/engines/machine_clock.h"
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
// A unit changed in a cycle before the one its nextChange gave (a bug of that unit's nextChange).
[[noreturn]] void throwLateChange(std::uint64_t now);
}  // namespace machine_run_detail

// Calls f on every unit of the groups, in the order given.
template <typename F, typename... Groups>
void forEachUnit(F&& f, Groups&... groups) {
  (machine_run_detail::each(groups, f), ...);
}

// Ticks the units of `groups` (each a unit, a std::vector of units or a std::optional unit)
// in the order given, every cycle. Returns the cycles the machine ran (wires.now() at the
// end); adds the cycles fast-forwarded to `fastForwarded`: after a quiet cycle, the cycles
// before the next timed event, in which nothing moves (counted from the first one's tick).
// Throws std::runtime_error on a deadlock.
template <MachineClock kClock = MachineClock::Repeating, typename... Groups>
std::uint64_t runMachine(ChannelRegistry& wires, std::uint64_t& fastForwarded, Groups&... groups) {
  // The frame ends with the first cycle after which no unit holds work and every FIFO is
  // empty. That state can only be entered by a cycle where something changed, and the
  // cycle after it changes nothing, so the check runs only on unchanged cycles: ending
  // there, the frame took one cycle less than the loop ran.
  // The unchanged cycles in a row the clock ticks or repeats (the cycles up to a timed
  // event count as one) before it reports a deadlock.
  constexpr std::uint64_t kDeadlockCycles = 1000000;
  std::uint64_t quiet = 0;
  bool prevChanged = false;
  // Repeated ticks: when armed (repeatUntil != 0), this cycle's tick is counted and repeated
  // up to cycle repeatUntil - 1; `toEvent`: up to a timed event (a fast-forward).
  std::uint64_t repeatUntil = 0;
  bool toEvent = false;
  std::vector<TickCounts> before;
  for (;;) {
    bool changed = false;
    const std::uint64_t now = wires.now();
    const bool armed = repeatUntil != 0;
    if (armed) {
      before.clear();
      forEachUnit([&](auto& u) { before.push_back(u.tickCounts()); }, groups...);
    }
    forEachUnit([&](auto& u) { changed |= u.tick(now); }, groups...);
    changed |= wires.endCycle();
    if (changed) {
      if (armed) machine_run_detail::throwLateChange(now);
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
    if (armed) {
      // Cycles wires.now() .. repeatUntil - 1 would tick as this one did. Up to a timed
      // event they count as one unchanged cycle; otherwise none is repeated past the
      // deadlock limit of unchanged cycles, so a deadlock is reported at the same cycle.
      if (!toEvent && ++quiet > kDeadlockCycles) machine_run_detail::throwDeadlock(wires.now());
      const std::uint64_t n =
          toEvent ? repeatUntil - wires.now() : std::min(repeatUntil - wires.now(), kDeadlockCycles - quiet);
      if (n > 0) {
        std::size_t i = 0;
        forEachUnit([&](auto& u) { u.repeatTick(before[i++], n); }, groups...);
        wires.skipTo(wires.now() + n);
        if (!toEvent) quiet += n;
      }
      repeatUntil = 0;
      toEvent = false;
      continue;
    }
    // Nothing moved: the next timed event.
    std::uint64_t next = Unit::kNoEvent;
    forEachUnit(
        [&](auto& u) {
          const std::uint64_t t = u.nextEvent();
          if (t < next) next = t;
        },
        groups...);
    if (next == Unit::kNoEvent || ++quiet > kDeadlockCycles) machine_run_detail::throwDeadlock(wires.now());
    if constexpr (kClock == MachineClock::EveryCycle) continue;
    if (next > wires.now()) {
      // Nothing moves before it (fast-forwarded cycles): tick wires.now(), repeat it until then.
      fastForwarded += next - wires.now();
      repeatUntil = next;
      toEvent = true;
      continue;
    }
    // The first cycle from now on at which any tick may differ from this one's.
    std::uint64_t change = Unit::kNoEvent;
    forEachUnit(
        [&](auto& u) {
          const std::uint64_t t = u.nextChange(wires.now());
          if (t < change) change = t;
        },
        groups...);
    if (change > wires.now() + 1) repeatUntil = change;  // tick wires.now(), repeat it until then
  }
  return wires.now();
}

// runMachine with the clock chosen at run time.
template <typename... Groups>
std::uint64_t runMachine(MachineClock clock, ChannelRegistry& wires, std::uint64_t& fastForwarded, Groups&... groups) {
  return clock == MachineClock::EveryCycle ? runMachine<MachineClock::EveryCycle>(wires, fastForwarded, groups...)
                                           : runMachine<MachineClock::Repeating>(wires, fastForwarded, groups...);
}

// Appends every unit's counters to `out`, in the order given.
template <typename... Groups>
void appendUnitStats(std::vector<UnitStats>& out, Groups&... groups) {
  forEachUnit([&](auto& u) { out.push_back(u.stats()); }, groups...);
}

}  // namespace qacc
