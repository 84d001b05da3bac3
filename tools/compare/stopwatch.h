// Host wall time of the comparison's runs, in milliseconds.
#pragma once
#include <chrono>

namespace qacc::compare {

using Clock = std::chrono::steady_clock;
inline double msSince(Clock::time_point t0) {
  return std::chrono::duration<double, std::milli>(Clock::now() - t0).count();
}

}  // namespace qacc::compare
