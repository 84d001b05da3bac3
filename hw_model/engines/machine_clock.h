// MachineClock: how the clock of hw-cycle (engines/machine_run.h) goes through the cycles.
// Both count every cycle as ticking it counts; the engines repeat one tick's counts over the
// cycles that cannot differ from it, and the tests check that against ticking each cycle.
#pragma once

namespace qacc {

enum class MachineClock {
  Repeating,   // one tick's counts repeated up to the next timed event or change (the engines)
  EveryCycle,  // every cycle ticked (the check of the repeats; a wait of over a million
               // cycles is reported as a deadlock)
};

}  // namespace qacc
