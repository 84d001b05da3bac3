#include "raster/metrics/ssim.h"

#include <algorithm>
#include <cmath>
#include <stdexcept>
#include <vector>

namespace qacc {

ImageF luma(const Image8& img) {
  ImageF y(img.width, img.height, 1);
  for (std::size_t i = 0; i < img.pixels(); ++i) {
    if (img.channels >= 3) {
      const std::uint8_t* p = &img.data[i * std::size_t(img.channels)];
      y.data[i] = float(0.299 * p[0] + 0.587 * p[1] + 0.114 * p[2]);
    } else {
      y.data[i] = float(img.data[i * std::size_t(img.channels)]);
    }
  }
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

}  // namespace

SsimResult ssimMap(const Image8& a, const Image8& b) {
  if (!a.sameShape(b)) throw std::invalid_argument("ssim: images differ in shape");
  const int w = a.width, h = a.height;
  SsimResult r;
  r.map = ImageF(w, h, 1, 1.0f);
  if (w == 0 || h == 0) return r;
  const ImageF ya = luma(a), yb = luma(b);
  const double L = 255.0, C1 = (0.01 * L) * (0.01 * L), C2 = (0.03 * L) * (0.03 * L);
  const std::vector<double> k = gaussianKernel1d();

  // Window centres: the valid region when the image is large enough, else every pixel.
  const bool validX = w >= 2 * kRadius + 1, validY = h >= 2 * kRadius + 1;
  const int x0 = validX ? kRadius : 0, x1 = validX ? w - kRadius : w;
  const int y0 = validY ? kRadius : 0, y1 = validY ? h - kRadius : h;

  // Separable filtering of the five moments: horizontal pass into rows, then vertical.
  const std::size_t n = std::size_t(w) * std::size_t(h);
  std::vector<double> hx[5];
  for (auto& v : hx) v.assign(n, 0.0);
  for (int y = 0; y < h; ++y)
    for (int x = x0; x < x1; ++x) {
      double s[5] = {0, 0, 0, 0, 0}, ws = 0;
      for (int d = -kRadius; d <= kRadius; ++d) {
        const int xx = x + d;
        if (xx < 0 || xx >= w) continue;
        const double wt = k[std::size_t(d + kRadius)];
        const double p = ya.data[std::size_t(y) * w + xx], q = yb.data[std::size_t(y) * w + xx];
        s[0] += wt * p; s[1] += wt * q; s[2] += wt * p * p; s[3] += wt * q * q; s[4] += wt * p * q;
        ws += wt;
      }
      for (int m = 0; m < 5; ++m) hx[m][std::size_t(y) * w + x] = s[m] / ws;
    }
  double total = 0;
  std::size_t count = 0;
  for (int y = y0; y < y1; ++y)
    for (int x = x0; x < x1; ++x) {
      double s[5] = {0, 0, 0, 0, 0}, ws = 0;
      for (int d = -kRadius; d <= kRadius; ++d) {
        const int yy = y + d;
        if (yy < 0 || yy >= h) continue;
        const double wt = k[std::size_t(d + kRadius)];
        for (int m = 0; m < 5; ++m) s[m] += wt * hx[m][std::size_t(yy) * w + x];
        ws += wt;
      }
      for (double& v : s) v /= ws;
      const double mx = s[0], my = s[1];
      const double vx = s[2] - mx * mx, vy = s[3] - my * my, cxy = s[4] - mx * my;
      const double v = ((2 * mx * my + C1) * (2 * cxy + C2)) / ((mx * mx + my * my + C1) * (vx + vy + C2));
      r.map.at(x, y) = float(v);
      total += v;
      ++count;
    }
  // Border pixels outside the valid region take the nearest valid value (for heat maps).
  for (int y = 0; y < h; ++y)
    for (int x = 0; x < w; ++x) {
      if (x >= x0 && x < x1 && y >= y0 && y < y1) continue;
      r.map.at(x, y) = r.map.at(std::clamp(x, x0, x1 - 1), std::clamp(y, y0, y1 - 1));
    }
  r.mean = count ? total / double(count) : 1.0;
  return r;
}

double ssim(const Image8& a, const Image8& b) { return ssimMap(a, b).mean; }

}  // namespace qacc
