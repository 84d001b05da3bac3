#include "raster/image/heat_map.h"

#include <algorithm>
#include <cmath>
#include <stdexcept>

#include "raster/metrics/ssim.h"

namespace qacc {

namespace {
struct Stop {
  double t, r, g, b;
};
constexpr Stop kRamp[] = {{0.00, 0, 0, 0},       {0.20, 30, 40, 160},  {0.45, 170, 40, 170},
                          {0.70, 240, 120, 40},  {0.90, 250, 230, 60}, {1.00, 255, 255, 255}};
}  // namespace

Image8 heatMap(const ImageF& values, double max_value) {
  Image8 out(values.width, values.height, 3);
  const double m = max_value > 0 ? max_value : 1.0;
  for (std::size_t i = 0; i < values.pixels(); ++i) {
    double t = std::isfinite(values.data[i]) ? std::clamp(double(values.data[i]) / m, 0.0, 1.0) : 1.0;
    std::size_t k = 1;
    while (k + 1 < std::size(kRamp) && t > kRamp[k].t) ++k;
    const Stop& a = kRamp[k - 1];
    const Stop& b = kRamp[k];
    const double u = std::clamp((t - a.t) / (b.t - a.t), 0.0, 1.0);
    out.data[i * 3 + 0] = std::uint8_t(std::lround(a.r + u * (b.r - a.r)));
    out.data[i * 3 + 1] = std::uint8_t(std::lround(a.g + u * (b.g - a.g)));
    out.data[i * 3 + 2] = std::uint8_t(std::lround(a.b + u * (b.b - a.b)));
  }
  return out;
}

ImageF lumaDifference(const Image8& a, const Image8& b) {
  if (!a.sameShape(b)) throw std::invalid_argument("lumaDifference: images differ in shape");
  const ImageF ya = luma(a), yb = luma(b);
  ImageF d(a.width, a.height, 1);
  for (std::size_t i = 0; i < d.data.size(); ++i) d.data[i] = std::abs(ya.data[i] - yb.data[i]);
  return d;
}

void blit(Image8& dst, const Image8& src, int x0, int y0) {
  for (int y = 0; y < src.height; ++y)
    for (int x = 0; x < src.width; ++x) {
      const int X = x0 + x, Y = y0 + y;
      if (X < 0 || Y < 0 || X >= dst.width || Y >= dst.height) continue;
      for (int c = 0; c < 3; ++c) dst.at(X, Y, c) = src.at(x, y, src.channels >= 3 ? c : 0);
    }
}

}  // namespace qacc
