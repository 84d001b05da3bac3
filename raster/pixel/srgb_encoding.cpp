#include "raster/pixel/srgb_encoding.h"

#include <algorithm>
#include <cmath>
#include <limits>

#include "modeling/support/double_bits.h"

namespace qacc {

std::uint8_t linearToSrgb8Formula(double v) {
  v = std::clamp(v, 0.0, 1.0);
  const double s = v <= 0.0031308 ? 12.92 * v : 1.055 * std::pow(v, 1.0 / 2.4) - 0.055;
  return static_cast<std::uint8_t>(std::lround(s * 255.0));
}

namespace {

constexpr double kLinearEnd = 0.0031308;  // the formula's linear segment ends here (inclusive)
// Buckets of the start table: a positive double's exponent and top 8 mantissa bits, from the
// binade of 2^-9 (which holds kLinearEnd) up to 1.0.
constexpr int kBucketShift = 52 - 8;
constexpr double kGuard = 0x1p-32;  // relative half-width of the band around a boundary

struct SrgbTables {
  int first = 0;            // the byte just above kLinearEnd
  std::uint8_t atOne = 0;   // the byte of 1.0 (and of everything the clamp maps to it)
  double lo[257] = {};      // lo[k]: the smallest double above kLinearEnd giving k or more (k > first)
  double guardLo[257] = {}, guardHi[257] = {};
  std::uint64_t base = 0;   // bucket index of 2^-9
  std::uint8_t start[9 * 256 + 1] = {};

  SrgbTables() {
    first = linearToSrgb8Formula(std::nextafter(kLinearEnd, 2.0));
    atOne = linearToSrgb8Formula(1.0);
    // Boundaries by bisection over the ordered bit patterns of (kLinearEnd, 1].
    for (int k = 0; k <= 256; ++k) {
      lo[k] = k <= first ? kLinearEnd : std::numeric_limits<double>::infinity();
      guardLo[k] = -std::numeric_limits<double>::infinity();
      guardHi[k] = std::numeric_limits<double>::infinity();
    }
    for (int k = first + 1; k <= atOne; ++k) {
      std::uint64_t a = doubleBits(kLinearEnd), b = doubleBits(1.0);  // formula(a) < k <= formula(b)
      while (b - a > 1) {
        const std::uint64_t m = a + (b - a) / 2;
        if (linearToSrgb8Formula(doubleFromBits(m)) >= k) b = m;
        else a = m;
      }
      lo[k] = doubleFromBits(b);
      guardLo[k] = lo[k] * (1 + kGuard);
      guardHi[k] = lo[k] * (1 - kGuard);
    }
    guardLo[first] = kLinearEnd * (1 + kGuard);
    base = doubleBits(0x1p-9) >> kBucketShift;
    for (std::uint64_t i = 0; i < std::size(start); ++i) {
      const double low = doubleFromBits((base + i) << kBucketShift);
      int k = first;
      while (k < atOne && low >= lo[k + 1]) ++k;
      start[i] = std::uint8_t(k);
    }
  }
};

const SrgbTables& tables() {
  static const SrgbTables t;
  return t;
}

}  // namespace

std::uint8_t linearToSrgb8(double v) {
  const SrgbTables& t = tables();
  if (!(v > kLinearEnd)) return linearToSrgb8Formula(v);  // the linear segment, zero, negatives, NaN
  if (v >= 1.0) return t.atOne;                             // clamped to 1 (and +inf)
  int k = t.start[(doubleBits(v) >> kBucketShift) - t.base];
  while (v >= t.lo[k + 1]) ++k;
  if (v < t.guardLo[k] || v >= t.guardHi[k + 1]) return linearToSrgb8Formula(v);
  return std::uint8_t(k);
}

std::array<std::uint8_t, 3> toSrgb8(const Eigen::Vector3d& c) {
  return {linearToSrgb8(c.x()), linearToSrgb8(c.y()), linearToSrgb8(c.z())};
}

}  // namespace qacc
