#include "raster/metrics/silhouette_distance.h"

#include <algorithm>
#include <cmath>
#include <limits>
#include <stdexcept>

#include "raster/metrics/distance_transform.h"

namespace qacc {

namespace {

// Whether pixel (x, y) is a boundary pixel of the id buffer (silhouette_distance.h).
inline bool onBoundary(const UninitVector<std::int32_t>& ids, int width, int height, int x, int y) {
  const std::size_t i = std::size_t(y) * width + x;
  const std::int32_t id = ids[i];
  if (id < 0) return false;
  return (x > 0 && ids[i - 1] != id) || (x + 1 < width && ids[i + 1] != id) ||
         (y > 0 && ids[i - std::size_t(width)] != id) || (y + 1 < height && ids[i + std::size_t(width)] != id);
}

}  // namespace

std::vector<std::uint8_t> boundaryMask(const UninitVector<std::int32_t>& ids, int width, int height) {
  std::vector<std::uint8_t> m(std::size_t(width) * std::size_t(height), 0);
  for (int y = 0; y < height; ++y)
    for (int x = 0; x < width; ++x) m[std::size_t(y) * width + x] = onBoundary(ids, width, height, x, y);
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
  SilhouetteDistance s;
  s.tolerance = tolerance;
  if (std::equal(reference.object.begin(), reference.object.end(), test.object.begin())) {
    // The same ids: the same boundary pixels, each at distance 0 from the other set. The
    // figures the transforms below would give, without them (a sweep over timing knobs
    // meets this at every point): both counts the boundary's size, distances 0, and every
    // reference boundary pixel within any tolerance >= 0.
    std::size_t n = 0;
    for (int y = 0; y < h; ++y)
      for (int x = 0; x < w; ++x) n += onBoundary(reference.object, w, h, x, y);
    s.reference_boundary = s.test_boundary = n;
    if (n == 0) return s;
    s.hausdorff = 0;
    s.mean = 0;
    s.within_tolerance = 0.0 <= tolerance ? 1.0 : 0.0;
    return s;
  }
  double maxd = 0, sumRef = 0, sumTest = 0;
  std::size_t within = 0;
  // Distances from the boundary pixels of `from` to the boundary of `to`: the boundaries are
  // read from the ids where they are needed, and one distance transform is alive at a time
  // (no frame-sized mask: the accuracy line runs beside two frame buffers).
  const auto measure = [&](const UninitVector<std::int32_t>& from, const UninitVector<std::int32_t>& to,
                           std::size_t& count, double& sum, std::size_t* withinTolerance) {
    const auto dt = squaredDistanceTransformOf([&](int x, int y) { return onBoundary(to, w, h, x, y); }, w, h);
    for (int y = 0; y < h; ++y)
      for (int x = 0; x < w; ++x)
        if (onBoundary(from, w, h, x, y)) {
          ++count;
          const double d = distance(dt[std::size_t(y) * w + x]);
          maxd = std::max(maxd, d);
          sum += d;
          if (withinTolerance && d <= tolerance) ++*withinTolerance;
        }
  };
  measure(reference.object, test.object, s.reference_boundary, sumRef, &within);
  measure(test.object, reference.object, s.test_boundary, sumTest, nullptr);
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
