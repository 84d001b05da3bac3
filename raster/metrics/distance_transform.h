// Exact Euclidean distance transform of a binary image in O(n) (Felzenszwalb &
// Huttenlocher, "Distance Transforms of Sampled Functions", 2012): the lower envelope of
// parabolas, one pass along rows then one along columns.
#pragma once
#include <cstdint>
#include <vector>

namespace qacc {

// For a width x height mask (row-major, non-zero = feature), the squared Euclidean
// distance in pixels from every pixel to the nearest feature pixel (+inf when the mask
// has no feature at all).
std::vector<double> squaredDistanceTransform(const std::vector<std::uint8_t>& mask, int width, int height);

}  // namespace qacc
