// Unit: the common shape of every timed unit of the accelerator (design §3.2): a name, a
// tick() called once per modeled cycle, and busy / stall / idle cycle counters.
//  - busy:  the unit holds or accepted work this cycle and made progress;
//  - stall: it had a finished result but could not hand it on (full channel, busy bank);
//  - idle:  nothing to do.
// Every unit derives from Unit (its counters) and has, by name, what the clock
// (engines/machine_run.h) calls on it:
//  - bool tick(std::uint64_t now): one cycle; true when the unit changed any state (the
//    clock repeats one tick's counts over cycles where nothing happens);
//  - bool holdsWork() const: true while the unit holds work (in flight or buffered);
//  - std::uint64_t nextEvent() const: the earliest future cycle at which the unit will act
//    without new input, or count its tick differently (the clock fast-forwards to it;
//    Unit::kNoEvent: none; Unit's own nextEvent for a unit that never does);
//  - std::uint64_t nextChange(std::uint64_t now) const: for a unit whose tick in the cycle
//    before `now` changed nothing, the first cycle from `now` on at which its tick may do
//    anything else — change state, or count the cycle differently (busy / stall / idle) —
//    if no other unit changes anything first (Unit::kNoEvent: never). Never later than
//    that cycle; earlier is allowed (Unit's own, `now`, says "at once", for units without
//    it); the clock repeats such a tick over the cycles before it (runMachine);
//  - TickCounts tickCounts() const and repeatTick(const TickCounts& before, n): what one
//    tick counts, and that tick repeated n more times (a unit with per-tick state besides its
//    counters, such as the Z unit's round-robin pointer, advances it too).
// The clock ticks the units through their concrete types (no virtual call: a tick is
// inlined into the loop), so the tick bodies the loop runs every cycle are in the headers.
// Every unit has its own `Params`, derived from the flat configuration (HwConfig) by
// `Params::from`, which owns the unit's latency formula; units talk through channels
// (channel.h) and carry tokens (tokens.h); the arithmetic is the datapath's (datapath/),
// whose results for each pixel come from the pixel trace.
#pragma once
#include <cstdint>
#include <limits>
#include <string>

#include "hw_model/report/hw_stats.h"

namespace qacc {

// The counters one tick may move without changing the machine's state.
struct TickCounts {
  std::uint64_t busy = 0, stall = 0, idle = 0;
  std::uint64_t extra = 0;  // a unit's own per-tick count (the Z unit's bank conflicts)
};

class Unit {
 public:
  static constexpr std::uint64_t kNoEvent = std::numeric_limits<std::uint64_t>::max();
  explicit Unit(std::string name) { stats_.name = std::move(name); }
  // A unit that never acts without new input (units that do hide this with their own).
  std::uint64_t nextEvent() const { return kNoEvent; }
  // A unit that does not know when its tick next differs: at once (no repeated ticks).
  std::uint64_t nextChange(std::uint64_t now) const { return now; }
  TickCounts tickCounts() const { return {stats_.busy, stats_.stall, stats_.idle, 0}; }
  // The tick whose counters moved from `before` to now, repeated n more times.
  void repeatTick(const TickCounts& before, std::uint64_t n) {
    stats_.busy += n * (stats_.busy - before.busy);
    stats_.stall += n * (stats_.stall - before.stall);
    stats_.idle += n * (stats_.idle - before.idle);
  }
  const UnitStats& stats() const { return stats_; }
  // Takes back one idle cycle (the engine ticked every unit once past the end of the frame).
  void retractIdle() { --stats_.idle; }

 protected:
  void countBusy() { ++stats_.busy; }
  void countStall() { ++stats_.stall; }
  void countIdle() { ++stats_.idle; }
  void countItem() { ++stats_.items; }
  // One cycle of a unit that can stall on its output: a stall when it wanted to move and
  // nothing moved, busy when something moved or it holds work, idle otherwise.
  void countCycle(bool changed, bool stalled, bool holding) {
    if (stalled && !changed) countStall();
    else if (changed || holding) countBusy();
    else countIdle();
  }
  UnitStats stats_;
};

}  // namespace qacc
