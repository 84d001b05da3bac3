#include "raster/metrics/distance_transform.h"

#include <algorithm>
#include <limits>

namespace qacc {

namespace {

constexpr double kInf = std::numeric_limits<double>::infinity();

// 1-D squared distance transform of f (length n) into d, with scratch buffers v, z.
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

}  // namespace

std::vector<std::uint32_t> squaredDistanceTransform(const std::vector<std::uint8_t>& mask, int width, int height) {
  const std::size_t n = std::size_t(width) * std::size_t(height);
  std::vector<std::uint32_t> out(n, kNoFeature);
  if (n == 0) return out;
  const auto toDouble = [](std::uint32_t v) { return v == kNoFeature ? kInf : double(v); };
  const auto toInt = [](double v) { return v == kInf ? kNoFeature : std::uint32_t(v); };
  // Columns first, then rows; every line is independent (same result for any thread count).
#pragma omp parallel
  {
    std::vector<int> v;
    std::vector<double> z;
    std::vector<double> line(static_cast<std::size_t>(std::max(width, height))),
        res(static_cast<std::size_t>(std::max(width, height)));
#pragma omp for schedule(static)
    for (int x = 0; x < width; ++x) {
      for (int y = 0; y < height; ++y) line[std::size_t(y)] = mask[std::size_t(y) * width + x] ? 0.0 : kInf;
      dt1d(line.data(), height, res.data(), v, z);
      for (int y = 0; y < height; ++y) out[std::size_t(y) * width + x] = toInt(res[std::size_t(y)]);
    }
#pragma omp for schedule(static)
    for (int y = 0; y < height; ++y) {
      std::uint32_t* r = out.data() + std::size_t(y) * width;
      for (int x = 0; x < width; ++x) line[std::size_t(x)] = toDouble(r[x]);
      dt1d(line.data(), width, res.data(), v, z);
      for (int x = 0; x < width; ++x) r[x] = toInt(res[std::size_t(x)]);
    }
  }
  return out;
}

}  // namespace qacc
