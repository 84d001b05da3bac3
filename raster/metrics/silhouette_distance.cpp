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

// Distance in pixels from a squared distance transform's value.
double distance(std::uint32_t squared) {
  return squared == kNoFeature ? std::numeric_limits<double>::infinity() : std::sqrt(double(squared));
}

}  // namespace

SilhouetteDistance silhouetteDistance(const FrameBuffer& reference, const FrameBuffer& test, double tolerance) {
  checkSizes(reference, test);
  const int w = reference.width, h = reference.height;
  const auto ma = boundaryMask(reference.object, w, h);
  const auto mb = boundaryMask(test.object, w, h);
  SilhouetteDistance s;
  s.tolerance = tolerance;
  double maxd = 0, sumRef = 0, sumTest = 0;
  std::size_t within = 0;
  // Distances from the boundary pixels of `from` to the boundary of `to`, one distance
  // transform alive at a time.
  const auto measure = [&](const std::vector<std::uint8_t>& from, const std::vector<std::uint8_t>& to,
                           std::size_t& count, double& sum, std::size_t* withinTolerance) {
    const auto dt = squaredDistanceTransform(to, w, h);
    for (std::size_t i = 0; i < from.size(); ++i)
      if (from[i]) {
        ++count;
        const double d = distance(dt[i]);
        maxd = std::max(maxd, d);
        sum += d;
        if (withinTolerance && d <= tolerance) ++*withinTolerance;
      }
  };
  measure(ma, mb, s.reference_boundary, sumRef, &within);
  measure(mb, ma, s.test_boundary, sumTest, nullptr);
  const double sum = sumRef + sumTest;
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
    if (ma[i]) d = std::max(d, distance(db[i]));
    if (mb[i]) d = std::max(d, distance(da[i]));
    out.data[i] = float(d);
  }
  return out;
}

}  // namespace qacc
