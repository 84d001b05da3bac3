// Image metrics (design §4) on synthetic images with known answers.
#include <gtest/gtest.h>

#include <cmath>
#include <limits>
#include <random>

#include <omp.h>

#include "raster/metrics/coverage_error.h"
#include "raster/metrics/depth_error.h"
#include "raster/metrics/distance_transform.h"
#include "raster/metrics/psnr.h"
#include "raster/metrics/silhouette_distance.h"
#include "raster/metrics/ssim.h"

using namespace qacc;

namespace {

Image8 gray(int w, int h, std::uint8_t v) { return Image8(w, h, 1, v); }

// Frame buffer with a disc of object `id` centred at (cx, cy) with radius r.
FrameBuffer disc(int w, int h, double cx, double cy, double r, int id = 0) {
  FrameBuffer fb(w, h, {0, 0, 0});
  for (int y = 0; y < h; ++y)
    for (int x = 0; x < w; ++x) {
      const double dx = x + 0.5 - cx, dy = y + 0.5 - cy;
      if (dx * dx + dy * dy <= r * r) {
        const std::size_t i = std::size_t(y) * w + x;
        fb.object[i] = id;
        fb.depth[i] = 0.5;
        for (int c = 0; c < 3; ++c) fb.color.data[i * 3 + c] = 200;
      }
    }
  return fb;
}

}  // namespace

TEST(Psnr, IdenticalIsInfinite) {
  const FrameBuffer a = disc(40, 30, 20, 15, 8);
  EXPECT_TRUE(std::isinf(psnr(a, a)));
  EXPECT_GT(psnr(a, a), 0);
}

TEST(Psnr, KnownMse) {
  // One sample off by 255 among N samples: MSE = 255² / N, PSNR = 10 log10(N).
  Image8 a = gray(10, 10, 0), b = a;
  b.at(3, 4) = 255;
  EXPECT_NEAR(psnr(a, b), 10.0 * std::log10(100.0), 1e-12);
  // Uniform difference of 5 on every RGB sample: PSNR = 20 log10(255 / 5).
  Image8 c(8, 8, 3, 100), d(8, 8, 3, 105);
  EXPECT_NEAR(psnr(c, d), 20.0 * std::log10(255.0 / 5.0), 1e-12);
  EXPECT_THROW(psnr(gray(3, 3, 0), gray(4, 3, 0)), std::invalid_argument);
}

TEST(Ssim, IdenticalIsOne) {
  std::mt19937 rng(7);
  Image8 a(32, 24, 3);
  for (auto& v : a.data) v = std::uint8_t(rng() % 256);
  EXPECT_DOUBLE_EQ(ssim(a, a), 1.0);
}

TEST(Ssim, ConstantImagesByHand) {
  // Flat images: σ = 0 so only the luminance term remains: (2 a b + C1) / (a² + b² + C1).
  const double C1 = 6.5025;  // (0.01 * 255)²
  const double expected = (2 * 100.0 * 50.0 + C1) / (100.0 * 100.0 + 50.0 * 50.0 + C1);
  EXPECT_NEAR(ssim(gray(20, 20, 100), gray(20, 20, 50)), expected, 1e-9);
  // RGB flat images: luma 0.299*R + 0.587*G + 0.114*B.
  Image8 c(16, 16, 3), d(16, 16, 3, 0);
  for (std::size_t i = 0; i < c.pixels(); ++i) { c.data[i * 3] = 200; c.data[i * 3 + 1] = 0; c.data[i * 3 + 2] = 0; }
  const double ya = 0.299 * 200, yb = 0.0;
  EXPECT_NEAR(ssim(c, d), (2 * ya * yb + C1) / (ya * ya + yb * yb + C1), 1e-6);
}

TEST(Ssim, SingleWindowByHand) {
  // An 11x11 image has exactly one valid window. y = 255 − x gives μy = 255 − μx, σy = σx,
  // σxy = −σx², so SSIM = (2 μx μy + C1)(C2 − 2 σx²) / ((μx² + μy² + C1)(2 σx² + C2)).
  // The moments are computed here directly with the 2-D Gaussian weights.
  Image8 x(11, 11, 1), y(11, 11, 1);
  for (int j = 0; j < 11; ++j)
    for (int i = 0; i < 11; ++i) {
      x.at(i, j) = std::uint8_t((i * 37 + j * 11) % 200 + 20);
      y.at(i, j) = std::uint8_t(255 - x.at(i, j));
    }
  double wsum = 0, m = 0, m2 = 0;
  for (int j = 0; j < 11; ++j)
    for (int i = 0; i < 11; ++i) {
      const double w = std::exp(-((i - 5) * (i - 5) + (j - 5) * (j - 5)) / (2 * 1.5 * 1.5));
      wsum += w;
      m += w * x.at(i, j);
      m2 += w * double(x.at(i, j)) * x.at(i, j);
    }
  m /= wsum;
  m2 /= wsum;
  const double var = m2 - m * m, my = 255 - m;
  const double C1 = 6.5025, C2 = 58.5225;
  const double expected = (2 * m * my + C1) * (C2 - 2 * var) / ((m * m + my * my + C1) * (2 * var + C2));
  EXPECT_NEAR(ssim(x, y), expected, 1e-9);
  EXPECT_LT(expected, 0.0);  // anti-correlated structure
}

// SSIM and the distance transform run in parallel bands and lines: the same result for
// any thread count, and the mean without the map equals the map's mean.
TEST(Ssim, SameForAnyThreadCountAndWithoutTheMap) {
  std::mt19937 rng(5);
  Image8 a(301, 203, 3), b(301, 203, 3);
  for (auto& v : a.data) v = std::uint8_t(rng() % 256);
  for (std::size_t i = 0; i < b.data.size(); ++i) b.data[i] = std::uint8_t((a.data[i] + rng() % 40) % 256);
  const int saved = omp_get_max_threads();
  omp_set_num_threads(1);
  const SsimResult one = ssimMap(a, b);
  const double oneMean = ssim(a, b);
  std::vector<std::uint32_t> dt1;
  std::vector<std::uint8_t> mask(a.pixels());
  for (std::size_t i = 0; i < mask.size(); ++i) mask[i] = a.data[3 * i] < 3;
  dt1 = squaredDistanceTransform(mask, a.width, a.height);
  omp_set_num_threads(3);
  const SsimResult three = ssimMap(a, b);
  const double threeMean = ssim(a, b);
  const auto dt3 = squaredDistanceTransform(mask, a.width, a.height);
  omp_set_num_threads(saved);
  EXPECT_EQ(one.mean, three.mean);
  EXPECT_EQ(one.mean, oneMean);
  EXPECT_EQ(threeMean, oneMean);
  EXPECT_EQ(one.map.data, three.map.data);
  EXPECT_EQ(dt1, dt3);
  EXPECT_LT(one.mean, 0.99);
}

// The banded, vectorised filtering gives the same bits as the direct per-pixel separable
// sums (taps in ascending order, skipped outside the image) for every pixel of the map.
TEST(Ssim, MapEqualsTheDirectSeparableSums) {
  std::mt19937 rng(9);
  for (const auto& [w, h] : {std::pair{67, 45}, std::pair{9, 7}}) {
    Image8 a(w, h, 3), b(w, h, 3);
    for (auto& v : a.data) v = std::uint8_t(rng() % 256);
    for (std::size_t i = 0; i < b.data.size(); ++i) b.data[i] = std::uint8_t((a.data[i] * 3 + rng() % 60) % 256);
    const ImageF ya = luma(a), yb = luma(b);
    const int R = 5;
    std::vector<double> k(2 * R + 1);
    double ksum = 0;
    for (int i = -R; i <= R; ++i) ksum += (k[std::size_t(i + R)] = std::exp(-double(i * i) / (2 * 1.5 * 1.5)));
    for (double& v : k) v /= ksum;
    const bool vx = w >= 2 * R + 1, vy = h >= 2 * R + 1;
    const int x0 = vx ? R : 0, x1 = vx ? w - R : w, y0 = vy ? R : 0, y1 = vy ? h - R : h;
    std::vector<double> hx[5];
    for (auto& v : hx) v.assign(std::size_t(w) * h, 0.0);
    for (int y = 0; y < h; ++y)
      for (int x = x0; x < x1; ++x) {
        double s[5] = {0, 0, 0, 0, 0}, ws = 0;
        for (int d = -R; d <= R; ++d) {
          if (x + d < 0 || x + d >= w) continue;
          const double wt = k[std::size_t(d + R)], p = ya.at(x + d, y), q = yb.at(x + d, y);
          s[0] += wt * p; s[1] += wt * q; s[2] += wt * p * p; s[3] += wt * q * q; s[4] += wt * p * q;
          ws += wt;
        }
        for (int m = 0; m < 5; ++m) hx[m][std::size_t(y) * w + x] = s[m] / ws;
      }
    const SsimResult r = ssimMap(a, b);
    for (int y = y0; y < y1; ++y)
      for (int x = x0; x < x1; ++x) {
        double s[5] = {0, 0, 0, 0, 0}, ws = 0;
        for (int d = -R; d <= R; ++d) {
          if (y + d < 0 || y + d >= h) continue;
          const double wt = k[std::size_t(d + R)];
          for (int m = 0; m < 5; ++m) s[m] += wt * hx[m][std::size_t(y + d) * w + x];
          ws += wt;
        }
        for (double& v : s) v /= ws;
        const double C1 = 6.5025, C2 = 58.5225, mx = s[0], my = s[1];
        const double v = ((2 * mx * my + C1) * (2 * (s[4] - mx * my) + C2)) /
                         ((mx * mx + my * my + C1) * ((s[2] - mx * mx) + (s[3] - my * my) + C2));
        ASSERT_EQ(r.map.at(x, y), float(v)) << w << "x" << h << " at " << x << "," << y;
      }
  }
}

TEST(DistanceTransform, MatchesBruteForce) {
  std::mt19937 rng(3);
  const int w = 23, h = 17;
  std::vector<std::uint8_t> m(std::size_t(w) * h, 0);
  for (auto& v : m) v = (rng() % 29 == 0);
  m[5] = 1;
  const auto d = squaredDistanceTransform(m, w, h);
  for (int y = 0; y < h; ++y)
    for (int x = 0; x < w; ++x) {
      double best = std::numeric_limits<double>::infinity();
      for (int v = 0; v < h; ++v)
        for (int u = 0; u < w; ++u)
          if (m[std::size_t(v) * w + u]) best = std::min(best, double((x - u) * (x - u) + (y - v) * (y - v)));
      ASSERT_EQ(double(d[std::size_t(y) * w + x]), best) << x << "," << y;
    }
  const auto e = squaredDistanceTransform(std::vector<std::uint8_t>(6, 0), 3, 2);
  EXPECT_EQ(e[0], kNoFeature);
}

TEST(SilhouetteDistance, IdenticalIsZero) {
  const FrameBuffer a = disc(64, 48, 30, 20, 12);
  const SilhouetteDistance s = silhouetteDistance(a, a);
  EXPECT_GT(s.reference_boundary, 40u);
  EXPECT_EQ(s.hausdorff, 0.0);
  EXPECT_EQ(s.mean, 0.0);
  EXPECT_EQ(s.within_tolerance, 1.0);
}

TEST(SilhouetteDistance, TheSameIdsGiveWhatTheDistanceTransformsGive) {
  // Equal id buffers take a shortcut (no distance transforms). Background written as -2
  // instead of -1 changes no boundary pixel (a negative id is never on a boundary, and a
  // covered pixel's neighbour differs from it either way) but makes the buffers unequal, so
  // the transforms run: both must give the same figures, bit for bit, at any tolerance (NaN too).
  std::mt19937 rng(7);
  for (int trial = 0; trial < 20; ++trial) {
    const int w = 40 + int(rng() % 30), h = 30 + int(rng() % 20);
    FrameBuffer a(w, h, {0, 0, 0});
    for (int k = 0; k < trial % 5; ++k) {  // up to four overlapping discs (trial 0: none)
      const FrameBuffer d = disc(w, h, int(rng() % std::uint32_t(w)), int(rng() % std::uint32_t(h)), 3 + int(rng() % 12));
      for (std::size_t i = 0; i < a.object.size(); ++i)
        if (d.object[i] >= 0) a.object[i] = k;
    }
    FrameBuffer b = a;
    for (auto& id : b.object)
      if (id < 0) id = -2;
    for (const double tol : {1.0, 0.0, -1.0, std::nan("")}) {
      const SilhouetteDistance same = silhouetteDistance(a, a, tol), full = silhouetteDistance(a, b, tol);
      EXPECT_EQ(same.reference_boundary, full.reference_boundary) << trial;
      EXPECT_EQ(same.test_boundary, full.test_boundary) << trial;
      EXPECT_EQ(same.hausdorff, full.hausdorff) << trial;
      EXPECT_EQ(same.mean, full.mean) << trial;
      EXPECT_EQ(same.within_tolerance, full.within_tolerance) << trial << " tolerance " << tol;
    }
  }
}

TEST(SilhouetteDistance, OnePixelShiftIsOne) {
  const FrameBuffer a = disc(64, 48, 30, 20, 12), b = disc(64, 48, 31, 20, 12);
  const SilhouetteDistance s = silhouetteDistance(a, b);
  EXPECT_DOUBLE_EQ(s.hausdorff, 1.0);
  EXPECT_GT(s.mean, 0.2);
  EXPECT_LE(s.mean, 1.0);
  // A straight vertical edge shifted by one pixel: every boundary pixel is exactly 1 away.
  FrameBuffer c(20, 10, {0, 0, 0}), d(20, 10, {0, 0, 0});
  for (int y = 0; y < 10; ++y)
    for (int x = 0; x < 20; ++x) {
      if (x < 8) c.object[std::size_t(y) * 20 + x] = 0;
      if (x < 9) d.object[std::size_t(y) * 20 + x] = 0;
    }
  const SilhouetteDistance t = silhouetteDistance(c, d);
  EXPECT_EQ(t.reference_boundary, 10u);
  EXPECT_DOUBLE_EQ(t.hausdorff, 1.0);
  EXPECT_DOUBLE_EQ(t.mean, 1.0);
  EXPECT_DOUBLE_EQ(t.within_tolerance, 1.0);
  EXPECT_DOUBLE_EQ(silhouetteDistance(c, d, 0.5).within_tolerance, 0.0);
}

TEST(SilhouetteDistance, ThreePixelShift) {
  const FrameBuffer a = disc(64, 48, 30, 20, 12), b = disc(64, 48, 30, 23, 12);
  EXPECT_DOUBLE_EQ(silhouetteDistance(a, b).hausdorff, 3.0);
  const FrameBuffer empty(64, 48, {0, 0, 0});
  EXPECT_TRUE(std::isinf(silhouetteDistance(a, empty).hausdorff));
}

TEST(CoverageError, CountsEachKind) {
  FrameBuffer r(4, 1, {0, 0, 0}), t(4, 1, {0, 0, 0});
  r.object = {0, 1, 1, -1};
  t.object = {0, 2, -1, 3};
  const CoverageError e = coverageError(r, t);
  EXPECT_EQ(e.reference_covered, 3u);
  EXPECT_EQ(e.wrong_object, 1u);
  EXPECT_EQ(e.pinholes, 1u);
  EXPECT_EQ(e.spurious, 1u);
  EXPECT_EQ(e.union_covered, 4u);
  // Every class counts, over the union of covered pixels: 3 of 4.
  EXPECT_NEAR(e.wrongFraction(), 3.0 / 4.0, 1e-15);
  const Image8 m = coverageErrorMask(r, t);
  EXPECT_EQ(m.data, (UninitVector<std::uint8_t>{0, 1, 2, 3}));
}

TEST(CoverageError, SpuriousPixelsCountInTheFraction) {
  // The reference covers 2 pixels, the test those 2 and 6 more: 6 of 8 covered pixels are wrong.
  FrameBuffer r(8, 1, {0, 0, 0}), t(8, 1, {0, 0, 0});
  r.object = {0, 0, -1, -1, -1, -1, -1, -1};
  t.object = {0, 0, 1, 1, 1, 1, 1, 1};
  const CoverageError e = coverageError(r, t);
  EXPECT_EQ(e.spurious, 6u);
  EXPECT_NEAR(e.wrongFraction(), 6.0 / 8.0, 1e-15);
}

TEST(DepthError, Z24UnitsDoNotDependOnTheBufferWidth) {
  Camera cam;
  FrameBuffer r(1, 1, {0, 0, 0}), t(1, 1, {0, 0, 0});
  r.object = {0};
  t.object = {0};
  r.depth = {0.5};
  t.depth = {0.5 + 3.0 / 16777216.0};
  for (int bits : {8, 16, 24}) {
    const DepthError e = depthError(r, t, cam, bits);
    EXPECT_NEAR(e.max_z24, 3.0, 1e-6) << bits;
    EXPECT_NEAR(e.mean_z24, 3.0, 1e-6) << bits;
  }
}

TEST(DepthError, WindowLsbAndView) {
  Camera cam;
  cam.near = 1.0;
  cam.far = 11.0;
  EXPECT_NEAR(windowDepthToView(cam, 0.0), 1.0, 1e-12);
  EXPECT_NEAR(windowDepthToView(cam, 1.0), 11.0, 1e-12);
  // Check against the projection matrix: a point at view distance 3.
  const Eigen::Vector4d clip = cam.projection(1.0) * Eigen::Vector4d(0, 0, -3, 1);
  const double z = 0.5 * clip.z() / clip.w() + 0.5;
  EXPECT_NEAR(windowDepthToView(cam, z), 3.0, 1e-12);

  FrameBuffer r(3, 1, {0, 0, 0}), t(3, 1, {0, 0, 0});
  r.object = {0, 0, 1};
  t.object = {0, 0, 2};  // third pixel: different objects, not compared
  r.depth = {0.5, 0.25, 0.1};
  t.depth = {0.5 + 3.0 / 16777215.0, 0.25, 0.9};
  const DepthError e = depthError(r, t, cam);
  EXPECT_EQ(e.pixels, 2u);
  EXPECT_NEAR(e.max_lsb, 3.0, 1e-6);
  EXPECT_NEAR(e.mean_lsb, 1.5, 1e-6);
  EXPECT_NEAR(e.max_window, 3.0 / 16777215.0, 1e-15);
  EXPECT_NEAR(e.max_view, windowDepthToView(cam, t.depth[0]) - windowDepthToView(cam, 0.5), 1e-12);
}
