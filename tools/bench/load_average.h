// The machine's one-minute load average, printed by the benchmark commands beside their
// figures: on a shared machine it says how far the wall times can be trusted.
#pragma once

namespace qacc {

// getloadavg's one-minute figure, or -1 when the system does not give it.
double loadAverage();

}  // namespace qacc
