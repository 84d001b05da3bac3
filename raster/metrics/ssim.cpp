#include "raster/metrics/ssim.h"

#include <algorithm>
#include <cmath>
#include <stdexcept>
#include <vector>

namespace qacc {

namespace {
// Luma of pixels [first, first + count) of img into out.
void lumaPixels(const Image8& img, std::size_t first, std::size_t count, float* out) {
  for (std::size_t i = first; i < first + count; ++i) {
    if (img.channels >= 3) {
      const std::uint8_t* p = &img.data[i * std::size_t(img.channels)];
      out[i - first] = float(0.299 * p[0] + 0.587 * p[1] + 0.114 * p[2]);
    } else {
      out[i - first] = float(img.data[i * std::size_t(img.channels)]);
    }
  }
}
}  // namespace

ImageF luma(const Image8& img) {
  ImageF y(img.width, img.height, 1);
  lumaPixels(img, 0, img.pixels(), y.data.data());
  return y;
}

namespace {

constexpr int kRadius = 5;  // 11x11 window
constexpr double kSigma = 1.5;

std::vector<double> gaussianKernel1d() {
  std::vector<double> k(2 * kRadius + 1);
  double sum = 0;
  for (int i = -kRadius; i <= kRadius; ++i) {
    k[std::size_t(i + kRadius)] = std::exp(-double(i * i) / (2 * kSigma * kSigma));
    sum += k[std::size_t(i + kRadius)];
  }
  for (double& v : k) v /= sum;
  return k;
}

// The SSIM of every window centre in rows [ys, ye) of the valid region, written to `map`
// (when not null), and the sum of each row's values in rowTotal[y] (summed left to right).
// The separable filtering runs over the band's rows plus the window's reach above and
// below, in a buffer of the band's size: the moments never take a frame-sized buffer, and
// bands are independent, so they run in parallel with the same result for any thread count.
void ssimBand(const Image8& a, const Image8& b, const std::vector<double>& k, int x0, int x1, int ys, int ye,
              ImageF* map, double* rowTotal) {
  const double L = 255.0, C1 = (0.01 * L) * (0.01 * L), C2 = (0.03 * L) * (0.03 * L);
  const int w = a.width, h = a.height;
  const int r0 = std::max(0, ys - kRadius), r1 = std::min(h, ye + kRadius);
  const std::size_t n = std::size_t(w) * std::size_t(r1 - r0);
  // The luma of the band's rows (ya, yb hold rows r0 .. r1 - 1).
  std::vector<float> ya(n), yb(n);
  lumaPixels(a, std::size_t(r0) * w, n, ya.data());
  lumaPixels(b, std::size_t(r0) * w, n, yb.data());
  // Each sum runs over the window's taps in the same order as a per-pixel loop would
  // (d ascending, taps outside the image skipped), with the tap loop outside the pixel
  // loop so that the compiler vectorises across pixels.
  std::vector<double> hx[5];
  for (auto& v : hx) v.assign(n, 0.0);
  std::vector<double> acc[5], wsum(std::size_t(w), 0.0);
  for (auto& v : acc) v.assign(std::size_t(w), 0.0);
  for (int y = r0; y < r1; ++y) {
    const float* pa = ya.data() + std::size_t(y - r0) * w;
    const float* pb = yb.data() + std::size_t(y - r0) * w;
    for (auto& v : acc) std::fill(v.begin() + x0, v.begin() + x1, 0.0);
    std::fill(wsum.begin() + x0, wsum.begin() + x1, 0.0);
    for (int d = -kRadius; d <= kRadius; ++d) {
      const double wt = k[std::size_t(d + kRadius)];
      const int lo = std::max(x0, -d), hi = std::min(x1, w - d);  // taps x + d inside [0, w)
      double* __restrict s0 = acc[0].data();
      double* __restrict s1 = acc[1].data();
      double* __restrict s2 = acc[2].data();
      double* __restrict s3 = acc[3].data();
      double* __restrict s4 = acc[4].data();
      double* __restrict ws = wsum.data();
      for (int x = lo; x < hi; ++x) {
        const double p = pa[x + d], q = pb[x + d];
        s0[x] += wt * p; s1[x] += wt * q; s2[x] += wt * p * p; s3[x] += wt * q * q; s4[x] += wt * p * q;
        ws[x] += wt;
      }
    }
    for (int m = 0; m < 5; ++m) {
      double* out = hx[m].data() + std::size_t(y - r0) * w;
      for (int x = x0; x < x1; ++x) out[x] = acc[m][std::size_t(x)] / wsum[std::size_t(x)];
    }
  }
  for (int y = ys; y < ye; ++y) {
    for (auto& v : acc) std::fill(v.begin() + x0, v.begin() + x1, 0.0);
    double ws = 0;
    for (int d = -kRadius; d <= kRadius; ++d) {
      const int yy = y + d;
      if (yy < 0 || yy >= h) continue;
      const double wt = k[std::size_t(d + kRadius)];
      for (int m = 0; m < 5; ++m) {
        const double* in = hx[m].data() + std::size_t(yy - r0) * w;
        double* __restrict s = acc[m].data();
        for (int x = x0; x < x1; ++x) s[x] += wt * in[x];
      }
      ws += wt;
    }
    double total = 0;
    for (int x = x0; x < x1; ++x) {
      const double mx = acc[0][std::size_t(x)] / ws, my = acc[1][std::size_t(x)] / ws;
      const double vx = acc[2][std::size_t(x)] / ws - mx * mx, vy = acc[3][std::size_t(x)] / ws - my * my,
                   cxy = acc[4][std::size_t(x)] / ws - mx * my;
      const double v = ((2 * mx * my + C1) * (2 * cxy + C2)) / ((mx * mx + my * my + C1) * (vx + vy + C2));
      if (map) map->at(x, y) = float(v);
      total += v;
    }
    rowTotal[y] = total;
  }
}

// MSSIM of a and b, and the per-pixel map when `map` is not null.
double ssimImpl(const Image8& a, const Image8& b, ImageF* map) {
  if (!a.sameShape(b)) throw std::invalid_argument("ssim: images differ in shape");
  const int w = a.width, h = a.height;
  if (w == 0 || h == 0) return 1.0;
  const std::vector<double> k = gaussianKernel1d();

  // Window centres: the valid region when the image is large enough, else every pixel.
  const bool validX = w >= 2 * kRadius + 1, validY = h >= 2 * kRadius + 1;
  const int x0 = validX ? kRadius : 0, x1 = validX ? w - kRadius : w;
  const int y0 = validY ? kRadius : 0, y1 = validY ? h - kRadius : h;

  constexpr int kBand = 32;  // rows per band
  std::vector<double> rowTotal(std::size_t(h), 0.0);
  const int bands = (y1 - y0 + kBand - 1) / kBand;
#pragma omp parallel for schedule(dynamic)
  for (int bi = 0; bi < bands; ++bi) {
    const int ys = y0 + bi * kBand;
    ssimBand(a, b, k, x0, x1, ys, std::min(y1, ys + kBand), map, rowTotal.data());
  }
  double total = 0;
  for (int y = y0; y < y1; ++y) total += rowTotal[std::size_t(y)];
  const std::size_t count = std::size_t(x1 - x0) * std::size_t(y1 - y0);
  if (map) {
    // Border pixels outside the valid region take the nearest valid value (for heat maps).
    for (int y = 0; y < h; ++y)
      for (int x = 0; x < w; ++x) {
        if (x >= x0 && x < x1 && y >= y0 && y < y1) continue;
        map->at(x, y) = map->at(std::clamp(x, x0, x1 - 1), std::clamp(y, y0, y1 - 1));
      }
  }
  return count ? total / double(count) : 1.0;
}

}  // namespace

SsimResult ssimMap(const Image8& a, const Image8& b) {
  SsimResult r;
  r.map = ImageF(a.width, a.height, 1, 1.0f);
  r.mean = ssimImpl(a, b, &r.map);
  return r;
}

double ssim(const Image8& a, const Image8& b) { return ssimImpl(a, b, nullptr); }

}  // namespace qacc
