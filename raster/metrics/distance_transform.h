// Exact Euclidean distance transform of a binary image in O(n) (Felzenszwalb &
// Huttenlocher, "Distance Transforms of Sampled Functions", 2012): the lower envelope of
// parabolas, one pass along rows then one along columns.
#pragma once
#include <cstdint>
#include <vector>

namespace qacc {

// "No feature pixel at all": the value of every pixel of a mask without a feature.
constexpr std::uint32_t kNoFeature = 0xFFFFFFFFu;

// For a width x height mask (row-major, non-zero = feature), the squared Euclidean
// distance in pixels from every pixel to the nearest feature pixel (kNoFeature when the
// mask has no feature at all). Squared distances are integers below 2 * 16384^2 for every
// image size qacc accepts, so 32 bits hold them exactly at half the memory of doubles.
std::vector<std::uint32_t> squaredDistanceTransform(const std::vector<std::uint8_t>& mask, int width, int height);

}  // namespace qacc
