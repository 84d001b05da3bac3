// runMachine: the clock of hw-cycle. Ticks wired timed units (timing/unit.h) cycle by
// cycle until no unit holds work and every channel is empty, jumping over cycles where
// nothing moves to the next timed event (fast-forward). The units are passed by their
// concrete types, so every tick is a direct call the compiler can inline into the loop.
//
// Cycles where nothing moves but some unit waits without a timed event of its own (stalled
// on a full channel: a setup-bound frame, the host waiting on setup, traversal on the
// pipelines) are not fast-forwarded: each is ticked and counted (stall, busy, idle; the
// Z unit's conflicts and round-robin pointer advance). The clock does not tick them one by
// one either: after such a cycle it asks every unit for the first cycle at which its tick
// may differ (Unit::nextChange), ticks the next cycle as usual while noting every unit's
// counters before and after, and adds that tick's counts once for each further cycle up to
// that one (Unit::repeatTick): what ticking them would have counted, cycle for cycle.
#pragma once
#include <algorithm>
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
// end); adds the cycles skipped by fast-forward to `fastForwarded`. Throws
// std::runtime_error on a deadlock.
template <typename... Groups>
std::uint64_t runMachine(ChannelRegistry& wires, std::uint64_t& fastForwarded, Groups&... groups) {
  // The frame ends with the first cycle after which no unit holds work and every FIFO is
  // empty. That state can only be entered by a cycle where something changed, and the
  // cycle after it changes nothing, so the check runs only on unchanged cycles: ending
  // there, the frame took one cycle less than the loop ran.
  // The unchanged cycles in a row the clock ticks or repeats (a fast-forward jump counts as
  // one) before it reports a deadlock.
  constexpr std::uint64_t kDeadlockCycles = 1000000;
  std::uint64_t quiet = 0;
  bool prevChanged = false;
  // Repeated ticks: when armed (repeatUntil != 0), this cycle's tick is counted and repeated
  // up to cycle repeatUntil - 1.
  std::uint64_t repeatUntil = 0;
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
    // Nothing moved: jump to the next timed event.
    std::uint64_t next = Unit::kNoEvent;
    forEachUnit(
        [&](auto& u) {
          const std::uint64_t t = u.nextEvent();
          if (t < next) next = t;
        },
        groups...);
    if (next == Unit::kNoEvent || ++quiet > kDeadlockCycles) machine_run_detail::throwDeadlock(wires.now());
    if (next > wires.now()) {
      const std::uint64_t skip = next - wires.now();
      forEachUnit([&](auto& u) { u.skip(skip, u.holdsWork()); }, groups...);
      fastForwarded += skip;
      wires.skipTo(next);
      repeatUntil = 0;
      continue;
    }
    if (armed) {
      // Cycles wires.now() .. repeatUntil - 1 would tick as this one did (none past the
      // deadlock limit of unchanged cycles, so a deadlock is reported at the same cycle).
      const std::uint64_t n = std::min(repeatUntil - wires.now(), kDeadlockCycles - quiet);
      if (n > 0) {
        std::size_t i = 0;
        forEachUnit([&](auto& u) { u.repeatTick(before[i++], n); }, groups...);
        quiet += n;
        wires.skipTo(wires.now() + n);
      }
      repeatUntil = 0;
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

// Appends every unit's counters to `out`, in the order given.
template <typename... Groups>
void appendUnitStats(std::vector<UnitStats>& out, Groups&... groups) {
  forEachUnit([&](auto& u) { out.push_back(u.stats()); }, groups...);
}

}  // namespace qacc
