#include "hw_model/engines/machine_run.h"

#include <stdexcept>
#include <string>

namespace qacc::machine_run_detail {

void throwDeadlock(std::uint64_t now) {
  throw std::runtime_error("hw-cycle: the pipeline deadlocked at cycle " + std::to_string(now));
}

void throwLateChange(std::uint64_t now) {
  throw std::logic_error("hw-cycle: a unit changed at cycle " + std::to_string(now) +
                         ", before the cycle its nextChange gave (the clock's repeated ticks)");
}

}  // namespace qacc::machine_run_detail
