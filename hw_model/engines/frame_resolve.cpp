#include "hw_model/engines/frame_resolve.h"

#include <omp.h>

#include <algorithm>
#include <array>
#include <cmath>

#include "raster/pixel/shading.h"

namespace qacc {

std::uint64_t resolveRow(const HwConfig& cfg, const FrameSetup& fs, int x0, int x1, int y, const ZEntry* row,
                         const FrameBuffer::Background& background, FrameBuffer& fb, OverflowCounter& ovf) {
  std::uint64_t written = 0;
  std::array<std::uint8_t, 3> rgb[256];
  for (int x = x0; x < x1;) {
    const ZEntry& e = row[x - x0];
    if (e.prim < 0) {  // the background up to the next winner
      int end = x + 1;
      while (end < x1 && row[end - x0].prim < 0) ++end;
      fb.clearRect(x, y, end, y + 1, background);
      x = end;
      continue;
    }
    // The run of this primitive's winners from x (at most 256 at a time).
    int end = x + 1;
    const int last = std::min(x1, x + 256);
    while (end < last && row[end - x0].prim == e.prim) ++end;
    const PrimitiveSetup& s = fs.setups[std::size_t(e.prim)];
    shadeSpan(s, fs.lighting, cfg, x - s.x0, y - s.y0, end - x, &e, rgb, ovf);
    for (int i = x; i < end; ++i) {
      const ZEntry& w = row[i - x0];
      const std::size_t pix = std::size_t(y) * std::size_t(fb.width) + std::size_t(i);
      for (int c = 0; c < 3; ++c) fb.color.data[pix * 3 + c] = rgb[i - x][std::size_t(c)];
      fb.depth[pix] = (double(w.z) + 0.5) * fs.storedDepthStep;
      fb.object[pix] = s.object;
      fb.primitive[pix] = w.prim;
    }
    written += std::uint64_t(end - x);
    x = end;
  }
  return written;
}

FrameBuffer resolveFrame(const Scene& scene, const HwConfig& cfg, const FrameSetup& fs, const ZBufferMemory& zb,
                         int threads, HwStats& stats) {
  const FrameBuffer::Background background(toSrgb8(scene.background));
  FrameBuffer fb = FrameBuffer::uninitialised(scene.width, scene.height);  // every pixel written below, in parallel
  const int nt = threads > 0 ? threads : omp_get_max_threads();
  std::uint64_t distinct = 0;
#pragma omp parallel for schedule(dynamic, 8) num_threads(nt) reduction(+ : distinct)
  for (int y = 0; y < scene.height; ++y) {
    OverflowCounter local;
    distinct += resolveRow(cfg, fs, 0, scene.width, y, &zb.px[zb.index(0, y)], background, fb, local);
  }
  stats.distinct_written = distinct;
  return fb;
}

}  // namespace qacc
