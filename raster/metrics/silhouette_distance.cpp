#include "raster/metrics/silhouette_distance.h"

#include <algorithm>
#include <cmath>
#include <limits>
#include <stdexcept>

#include "raster/metrics/distance_transform.h"

namespace qacc {

std::vector<std::uint8_t> boundaryMask(const UninitVector<std::int32_t>& ids, int width, int height) {
  std::vector<std::uint8_t> m(std::size_t(width) * std::size_t(height), 0);
  for (int y = 0; y < height; ++y)
    for (int x = 0; x < width; ++x) {
      const std::size_t i = std::size_t(y) * width + x;
      const std::int32_t id = ids[i];
      if (id < 0) continue;
      if ((x > 0 && ids[i - 1] != id) || (x + 1 < width && ids[i + 1] != id) ||
          (y > 0 && ids[i - std::size_t(width)] != id) || (y + 1 < height && ids[i + std::size_t(width)] != id))
        m[i] = 1;
    }
  return m;
}

namespace {

void checkSizes(const FrameBuffer& a, const FrameBuffer& b) {
  if (a.width != b.width || a.height != b.height || a.object.size() != b.object.size())
    throw std::invalid_argument("silhouetteDistance: frame buffers differ in size");
}

}  // namespace

SilhouetteDistance silhouetteDistance(const FrameBuffer& reference, const FrameBuffer& test, double tolerance) {
  checkSizes(reference, test);
  const int w = reference.width, h = reference.height;
  const auto ma = boundaryMask(reference.object, w, h);
  const auto mb = boundaryMask(test.object, w, h);
  const auto da = squaredDistanceTransform(ma, w, h);  // distance to the reference boundary
  const auto db = squaredDistanceTransform(mb, w, h);  // distance to the test boundary
  SilhouetteDistance s;
  s.tolerance = tolerance;
  double maxd = 0, sum = 0;
  std::size_t within = 0;
  for (std::size_t i = 0; i < ma.size(); ++i) {
    if (ma[i]) {
      ++s.reference_boundary;
      const double d = std::sqrt(db[i]);
      maxd = std::max(maxd, d);
      sum += d;
      if (d <= tolerance) ++within;
    }
    if (mb[i]) {
      ++s.test_boundary;
      const double d = std::sqrt(da[i]);
      maxd = std::max(maxd, d);
      sum += d;
    }
  }
  const std::size_t n = s.reference_boundary + s.test_boundary;
  if (n == 0) return s;  // neither has a boundary: identical silhouettes
  if (s.reference_boundary == 0 || s.test_boundary == 0) {
    s.hausdorff = s.mean = std::numeric_limits<double>::infinity();
    s.within_tolerance = s.reference_boundary == 0 ? 1.0 : 0.0;
    return s;
  }
  s.hausdorff = maxd;
  s.mean = sum / double(n);
  s.within_tolerance = double(within) / double(s.reference_boundary);
  return s;
}

ImageF silhouetteDistanceMap(const FrameBuffer& reference, const FrameBuffer& test) {
  checkSizes(reference, test);
  const int w = reference.width, h = reference.height;
  const auto ma = boundaryMask(reference.object, w, h);
  const auto mb = boundaryMask(test.object, w, h);
  const auto da = squaredDistanceTransform(ma, w, h);
  const auto db = squaredDistanceTransform(mb, w, h);
  ImageF out(w, h, 1, 0.0f);
  for (std::size_t i = 0; i < ma.size(); ++i) {
    double d = 0;
    if (ma[i]) d = std::max(d, std::sqrt(db[i]));
    if (mb[i]) d = std::max(d, std::sqrt(da[i]));
    out.data[i] = float(d);
  }
  return out;
}

}  // namespace qacc
