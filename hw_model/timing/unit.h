// Unit: the common shape of every timed unit of the accelerator (design §3.2): a name, a
// tick() called once per modeled cycle, and busy / stall / idle cycle counters.
//  - busy:  the unit holds or accepted work this cycle and made progress;
//  - stall: it had a finished result but could not hand it on (full channel, busy bank);
//  - idle:  nothing to do.
// tick() returns true when the unit changed any state (used by the cycle engine to detect
// cycles where nothing happens and fast-forward to the next timed event).
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

class Unit {
 public:
  explicit Unit(std::string name) { stats_.name = std::move(name); }
  virtual ~Unit() = default;
  virtual bool tick(std::uint64_t now) = 0;
  // Earliest future cycle at which the unit will act without new input (UINT64_MAX: none).
  virtual std::uint64_t nextEvent() const { return std::numeric_limits<std::uint64_t>::max(); }
  // True while the unit holds work (in flight or buffered).
  virtual bool holdsWork() const = 0;
  // Accounts `n` cycles skipped by fast-forward (nothing moved: busy if holding work).
  void skip(std::uint64_t n) {
    if (holdsWork()) stats_.busy += n;
    else stats_.idle += n;
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
