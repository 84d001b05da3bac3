// MachineClock: how hw-cycle's simulator goes through the cycles. All count every cycle as
// ticking it counts: the item clock computes the main pass's cycles item by item from the
// units' rules (engines/item_clock.h), the ticking clock (engines/machine_run.h) repeats one
// tick's counts over the cycles that cannot differ from it, and the tests check both against
// ticking each cycle.
#pragma once

namespace qacc {

enum class MachineClock {
  Items,       // the main pass timed item by item where that applies (engines/item_clock.h;
               // the engines' default), elsewhere and in the CSG pass as Repeating
  Repeating,   // one tick's counts repeated up to the next timed event or change
  EveryCycle,  // every cycle ticked (the check of the others; a wait of over a million
               // cycles is reported as a deadlock)
};

}  // namespace qacc
