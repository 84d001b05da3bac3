#include "tools/sweep/thumbnail.h"

#include <algorithm>

#include "raster/image/heat_map.h"
#include "raster/metrics/coverage_error.h"

namespace qacc {

namespace {
int factorFor(int width, int maxWidth) { return maxWidth > 0 ? std::max(1, (width + maxWidth - 1) / maxWidth) : 1; }
}  // namespace

Image8 thumbnail(const Image8& in, int maxWidth) {
  const int f = factorFor(in.width, maxWidth);
  const int w = std::max(1, in.width / f), h = std::max(1, in.height / f);
  Image8 out(w, h, in.channels);
  for (int y = 0; y < h; ++y)
    for (int x = 0; x < w; ++x)
      for (int c = 0; c < in.channels; ++c) {
        int sum = 0, n = 0;
        for (int dy = 0; dy < f && y * f + dy < in.height; ++dy)
          for (int dx = 0; dx < f && x * f + dx < in.width; ++dx, ++n)
            sum += in.data[(std::size_t(y * f + dy) * in.width + (x * f + dx)) * in.channels + c];
        out.data[(std::size_t(y) * w + x) * in.channels + c] = std::uint8_t((sum + n / 2) / std::max(n, 1));
      }
  return out;
}

Image8 errorMapThumbnail(const FrameBuffer& ref, const FrameBuffer& test, int maxWidth) {
  const Image8 heat = heatMap(lumaDifference(ref.color, test.color), 64.0);
  const Image8 mask = coverageErrorMask(ref, test);
  static const std::uint8_t paint[4][3] = {{0, 0, 0}, {255, 40, 40}, {255, 230, 0}, {0, 220, 255}};
  const int f = factorFor(ref.width, maxWidth);
  const int w = std::max(1, ref.width / f), h = std::max(1, ref.height / f);
  Image8 out(w, h, 3);
  for (int y = 0; y < h; ++y)
    for (int x = 0; x < w; ++x) {
      int worstClass = 0, worstHeat = -1;
      std::size_t worstPixel = 0;
      for (int dy = 0; dy < f && y * f + dy < ref.height; ++dy)
        for (int dx = 0; dx < f && x * f + dx < ref.width; ++dx) {
          const std::size_t i = std::size_t(y * f + dy) * ref.width + (x * f + dx);
          const int cls = mask.data[i];
          const int hv = heat.data[i * 3] + heat.data[i * 3 + 1] + heat.data[i * 3 + 2];
          if (cls > 0 && worstClass == 0) worstClass = cls;
          if (hv > worstHeat) {
            worstHeat = hv;
            worstPixel = i;
          }
        }
      std::uint8_t* o = &out.data[(std::size_t(y) * w + x) * 3];
      for (int c = 0; c < 3; ++c) o[c] = worstClass ? paint[worstClass][c] : heat.data[worstPixel * 3 + c];
    }
  return out;
}

}  // namespace qacc
