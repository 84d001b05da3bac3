// Exact Euclidean distance transform of a binary image in O(n) (Felzenszwalb &
// Huttenlocher, "Distance Transforms of Sampled Functions", 2012): the lower envelope of
// parabolas, one pass along rows then one along columns.
#pragma once
#include <algorithm>
#include <cstddef>
#include <cstdint>
#include <limits>
#include <vector>

namespace qacc {

// "No feature pixel at all": the value of every pixel of a mask without a feature.
constexpr std::uint32_t kNoFeature = 0xFFFFFFFFu;

namespace detail {
constexpr double kInf = std::numeric_limits<double>::infinity();
// 1-D squared distance transform of f (length n) into d, with scratch buffers v, z.
void dt1d(const double* f, int n, double* d, std::vector<int>& v, std::vector<double>& z);
}  // namespace detail

// For the features of a width x height image, isFeature(x, y), the squared Euclidean
// distance in pixels from every pixel to the nearest feature pixel (row-major; kNoFeature
// when there is no feature at all). Squared distances are integers below 2 * 16384^2 for
// every image size qacc accepts, so 32 bits hold them exactly at half the memory of doubles.
// The predicate is read once per pixel, so a feature that is a function of other buffers (a
// silhouette's boundary, silhouette_distance.h) needs no stored mask.
template <typename IsFeature>
std::vector<std::uint32_t> squaredDistanceTransformOf(IsFeature isFeature, int width, int height) {
  using detail::kInf;
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
      for (int y = 0; y < height; ++y) line[std::size_t(y)] = isFeature(x, y) ? 0.0 : kInf;
      detail::dt1d(line.data(), height, res.data(), v, z);
      for (int y = 0; y < height; ++y) out[std::size_t(y) * width + x] = toInt(res[std::size_t(y)]);
    }
#pragma omp for schedule(static)
    for (int y = 0; y < height; ++y) {
      std::uint32_t* r = out.data() + std::size_t(y) * width;
      for (int x = 0; x < width; ++x) line[std::size_t(x)] = toDouble(r[x]);
      detail::dt1d(line.data(), width, res.data(), v, z);
      for (int x = 0; x < width; ++x) r[x] = toInt(res[std::size_t(x)]);
    }
  }
  return out;
}

// The same for a mask (row-major, non-zero = feature).
inline std::vector<std::uint32_t> squaredDistanceTransform(const std::vector<std::uint8_t>& mask, int width,
                                                           int height) {
  return squaredDistanceTransformOf([&](int x, int y) { return mask[std::size_t(y) * width + x] != 0; }, width,
                                    height);
}

}  // namespace qacc
