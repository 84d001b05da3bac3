// The table-driven sRGB encoding gives the formula's byte for every double: at and around
// every boundary where the byte changes, across the whole range at random, and at the
// special values.
#include <gtest/gtest.h>

#include <cmath>
#include <cstdint>
#include <limits>
#include <random>

#include "modeling/support/double_bits.h"
#include "raster/pixel/srgb_encoding.h"

namespace qacc {
namespace {

void expectSame(double v) {
  ASSERT_EQ(int(linearToSrgb8(v)), int(linearToSrgb8Formula(v))) << "v = " << v << " (bits 0x" << std::hex
                                                                  << doubleBits(v) << ")";
}

TEST(SrgbEncoding, SameByteAsTheFormulaAtEveryBoundary) {
  // Each boundary found independently of the encoder (bisection with the formula), then
  // 2 000 doubles on each side of it: the band the encoder hands to the formula and beyond.
  int boundaries = 0;
  for (int k = 1; k <= 255; ++k) {
    std::uint64_t a = doubleBits(0.0), b = doubleBits(1.0);
    while (b - a > 1) {
      const std::uint64_t m = a + (b - a) / 2;
      if (linearToSrgb8Formula(doubleFromBits(m)) >= k) b = m;
      else a = m;
    }
    ++boundaries;
    for (std::int64_t d = -2000; d <= 2000; ++d) expectSame(doubleFromBits(std::uint64_t(std::int64_t(b) + d)));
    // Farther out, by relative steps that cross the encoder's band (2^-32).
    for (int e = 40; e >= 20; --e) {
      const double x = doubleFromBits(b);
      expectSame(x * (1 + std::ldexp(1.0, -e)));
      expectSame(x * (1 - std::ldexp(1.0, -e)));
    }
  }
  EXPECT_EQ(boundaries, 255);
}

TEST(SrgbEncoding, SameByteAsTheFormulaEverywhere) {
  std::mt19937_64 rng(20261129);
  std::uniform_real_distribution<double> unit(-0.05, 1.05);
  for (int i = 0; i < 2000000; ++i) expectSame(unit(rng));
  // Uniform over the bit patterns of (0, 1]: every binade, the darkest values included.
  std::uniform_int_distribution<std::uint64_t> bits(1, doubleBits(1.0));
  for (int i = 0; i < 2000000; ++i) expectSame(doubleFromBits(bits(rng)));
}

TEST(SrgbEncoding, SameByteAsTheFormulaAtSpecialValues) {
  const double inf = std::numeric_limits<double>::infinity();
  for (double v : {0.0, -0.0, 1.0, -1.0, 2.0, inf, -inf, std::numeric_limits<double>::quiet_NaN(),
                   std::numeric_limits<double>::denorm_min(), std::numeric_limits<double>::min(), 0.0031308,
                   std::nextafter(0.0031308, 1.0), std::nextafter(0.0031308, 0.0), std::nextafter(1.0, 0.0),
                   std::nextafter(1.0, 2.0), 0x1p-9, 0x1p-8, 0.5})
    expectSame(v);
  EXPECT_EQ(linearToSrgb8(0.0), 0);
  EXPECT_EQ(linearToSrgb8(1.0), 255);
  EXPECT_EQ(linearToSrgb8(0.5), 188);  // 1.055 · 0.5^(1/2.4) − 0.055 = 0.7354 → 187.5 → 188
}

}  // namespace
}  // namespace qacc
