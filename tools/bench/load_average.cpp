#include "tools/bench/load_average.h"

#include <cstdlib>

namespace qacc {

double loadAverage() {
  double l[1] = {0};
  return getloadavg(l, 1) == 1 ? l[0] : -1.0;
}

}  // namespace qacc
