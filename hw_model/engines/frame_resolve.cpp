#include "hw_model/engines/frame_resolve.h"

#include <omp.h>

#include <cmath>

#include "raster/pixel/shading.h"

namespace qacc {

void resolvePixel(const HwConfig& cfg, const FrameSetup& fs, int x, int y, const ZEntry& e, FrameBuffer& fb,
                  OverflowCounter& ovf) {
  const std::size_t pix = std::size_t(y) * std::size_t(fb.width) + std::size_t(x);
  const PrimitiveSetup& s = fs.setups[std::size_t(e.prim)];
  const auto rgb = shadePixel(s, fs.lighting, cfg, x - s.x0, y - s.y0, e.depth, e.cap, ovf);
  for (int c = 0; c < 3; ++c) fb.color.data[pix * 3 + c] = rgb[std::size_t(c)];
  fb.depth[pix] = (double(e.z) + 0.5) * fs.storedDepthStep;
  fb.object[pix] = s.object;
  fb.primitive[pix] = e.prim;
}

FrameBuffer resolveFrame(const Scene& scene, const HwConfig& cfg, const FrameSetup& fs, const ZBufferMemory& zb,
                         int threads, HwStats& stats) {
  const auto background = toSrgb8(scene.background);
  FrameBuffer fb = FrameBuffer::uninitialised(scene.width, scene.height);  // rows cleared below, in parallel
  const int nt = threads > 0 ? threads : omp_get_max_threads();
  std::uint64_t distinct = 0;
#pragma omp parallel for schedule(dynamic, 8) num_threads(nt) reduction(+ : distinct)
  for (int y = 0; y < scene.height; ++y) {
    OverflowCounter local;
    fb.clearRect(0, y, scene.width, y + 1, background);
    for (int x = 0; x < scene.width; ++x) {
      const std::size_t pix = std::size_t(y) * scene.width + x;
      if (zb.px[pix].prim < 0) continue;
      resolvePixel(cfg, fs, x, y, zb.px[pix], fb, local);
      ++distinct;
    }
  }
  stats.distinct_written = distinct;
  return fb;
}

}  // namespace qacc
