#include "raster/metrics/distance_transform.h"

#include <algorithm>
#include <limits>

namespace qacc {

namespace detail {

void dt1d(const double* f, int n, double* d, std::vector<int>& v, std::vector<double>& z) {
  v.resize(std::size_t(n));
  z.resize(std::size_t(n) + 1);
  int k = -1;
  for (int q = 0; q < n; ++q) {
    if (f[q] == kInf) continue;
    if (k < 0) {
      k = 0;
      v[0] = q;
      z[0] = -kInf;
      z[1] = kInf;
      continue;
    }
    double s;
    for (;;) {
      const int p = v[std::size_t(k)];
      s = ((f[q] + double(q) * q) - (f[p] + double(p) * p)) / (2.0 * (q - p));
      if (s <= z[std::size_t(k)] && k > 0) {
        --k;
        continue;
      }
      break;
    }
    if (s <= z[std::size_t(k)]) {  // k == 0 and the new parabola dominates everywhere
      v[0] = q;
      z[0] = -kInf;
      z[1] = kInf;
      continue;
    }
    ++k;
    v[std::size_t(k)] = q;
    z[std::size_t(k)] = s;
    z[std::size_t(k) + 1] = kInf;
  }
  if (k < 0) {
    std::fill(d, d + n, kInf);
    return;
  }
  int j = 0;
  for (int q = 0; q < n; ++q) {
    while (z[std::size_t(j) + 1] < q) ++j;
    const int p = v[std::size_t(j)];
    d[q] = double(q - p) * (q - p) + f[p];
  }
}

}  // namespace detail

}  // namespace qacc
