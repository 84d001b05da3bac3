// PNG and PFM round trips.
#include <gtest/gtest.h>

#include <cmath>
#include <filesystem>
#include <random>

#include "raster/image/frame_buffer.h"
#include "raster/image/pfm_io.h"
#include "raster/image/png_io.h"

using namespace qacc;

namespace {
std::string tmp(const std::string& name) {
  return (std::filesystem::temp_directory_path() / ("qacc_io_" + std::to_string(::getpid()) + "_" + name)).string();
}
}  // namespace

TEST(ImageIO, PngRgbRoundTrip) {
  std::mt19937 rng(1);
  Image8 img(37, 23, 3);
  for (auto& v : img.data) v = std::uint8_t(rng());
  const std::string p = tmp("rgb.png");
  writePng(p, img);
  const Image8 back = readPng(p);
  EXPECT_TRUE(back.sameShape(img));
  EXPECT_EQ(back.data, img.data);
  std::filesystem::remove(p);
}

TEST(ImageIO, Png16RoundTrip) {
  std::mt19937 rng(2);
  Image16 img(19, 31, 1);
  for (auto& v : img.data) v = std::uint16_t(rng());
  img.data[0] = 0;
  img.data[1] = 65535;
  img.data[2] = 256;
  const std::string p = tmp("ids.png");
  writePng16(p, img);
  const Image16 back = readPng16(p);
  EXPECT_TRUE(back.sameShape(img));
  EXPECT_EQ(back.data, img.data);
  std::filesystem::remove(p);
}

TEST(ImageIO, PfmRoundTripKeepsInfinityAndRowOrder) {
  ImageF img(5, 3, 1);
  for (std::size_t i = 0; i < img.data.size(); ++i) img.data[i] = float(i) * 0.25f;
  img.data[7] = std::numeric_limits<float>::infinity();
  const std::string p = tmp("d.pfm");
  writePfm(p, img);
  const ImageF back = readPfm(p);
  EXPECT_EQ(back.data, img.data);
  EXPECT_EQ(back.at(0, 0), 0.0f);
  EXPECT_TRUE(std::isinf(back.at(2, 1)));
  std::filesystem::remove(p);
}

TEST(ImageIO, ReadingAMissingFileThrows) {
  EXPECT_THROW(readPng("/nonexistent/x.png"), std::runtime_error);
  EXPECT_THROW(readPfm("/nonexistent/x.pfm"), std::runtime_error);
}

TEST(FrameBuffer, ClearRectFillsRowsOfEveryLengthWithTheColourInOrder) {
  // The colour is written 16 pixels at a time, then the rest: rows of 0 to 40 pixels from
  // every start, each channel in its place, nothing written outside.
  for (int x0 = 0; x0 < 3; ++x0)
    for (int n = 0; n <= 40; ++n) {
      FrameBuffer fb = FrameBuffer::uninitialised(45, 2);
      fb.clearRect(0, 0, 45, 2, {0, 0, 0});
      fb.clearRect(x0, 1, x0 + n, 2, {10, 20, 30});
      for (int y = 0; y < 2; ++y)
        for (int x = 0; x < 45; ++x) {
          const bool in = y == 1 && x >= x0 && x < x0 + n;
          for (int c = 0; c < 3; ++c)
            ASSERT_EQ(fb.color.at(x, y, c), in ? 10 * (c + 1) : 0) << "start " << x0 << ", length " << n << ", x " << x;
        }
    }
}

TEST(FrameBuffer, ClearRectWritesTheBackgroundInItsRectangleOnly) {
  FrameBuffer fb = FrameBuffer::uninitialised(5, 4);
  fb.clearRect(0, 0, 5, 4, {1, 2, 3});
  fb.object[0] = 7;
  fb.depth[0] = 0.5;
  fb.clearRect(1, 1, 4, 3, {9, 8, 7});
  for (int y = 0; y < 4; ++y)
    for (int x = 0; x < 5; ++x) {
      const std::size_t i = std::size_t(y) * 5 + std::size_t(x);
      const bool in = x >= 1 && x < 4 && y >= 1 && y < 3;
      EXPECT_EQ(fb.color.at(x, y, 0), in ? 9 : 1);
      EXPECT_EQ(fb.color.at(x, y, 2), in ? 7 : 3);
      if (i == 0) continue;
      EXPECT_EQ(fb.object[i], -1);
      EXPECT_EQ(fb.primitive[i], -1);
      EXPECT_TRUE(std::isinf(fb.depth[i]));
    }
  EXPECT_EQ(fb.object[0], 7);  // outside the rectangle: untouched
  EXPECT_EQ(fb.depth[0], 0.5);
  const FrameBuffer filled(5, 4, {4, 5, 6});  // the constructor clears the whole frame
  EXPECT_EQ(filled.covered(), 0u);
  EXPECT_EQ(filled.color.at(4, 3, 1), 5);
}
