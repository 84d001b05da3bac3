#include "hw_model/engines/frame_setup.h"

#include <omp.h>

#include <algorithm>
#include <cmath>
#include <limits>

#include "hw_model/timing/setup_unit.h"
#include "raster/pixel/shading.h"

namespace qacc {

HwSceneSetup HwSceneSetup::build(const Scene& scene, const HwConfig& cfg, int threads) {
  HwSceneSetup hs;
  const int n = int(scene.primitives.size());
  hs.setups.resize(std::size_t(n));
  const Eigen::Matrix4d M = scene.camera.worldToWindow(scene.width, scene.height);
  const Eigen::Matrix4d Minv = M.inverse();
  std::vector<OverflowCounter> ovf(static_cast<std::size_t>(n));
  const int nt = threads > 0 ? threads : omp_get_max_threads();
#pragma omp parallel for schedule(dynamic, 16) num_threads(nt)
  for (int i = 0; i < n; ++i) hs.setups[std::size_t(i)] = SetupUnit::run(scene, i, M, Minv, cfg, ovf[std::size_t(i)]);
  for (const auto& o : ovf) hs.overflow.setup.events += o.events;
  hs.lighting = LightingSetup::build(scene, cfg);
  return hs;
}

ZBufferState::ZBufferState(int w, int h)
    : width(w), height(h), px(std::size_t(w) * std::size_t(h)) {}

void resolvePixel(const HwConfig& cfg, const HwSceneSetup& hs, int x, int y, const ZEntry& e, FrameBuffer& fb,
                  OverflowCounter& ovf) {
  const std::size_t pix = std::size_t(y) * std::size_t(fb.width) + std::size_t(x);
  const PrimitiveSetup& s = hs.setups[std::size_t(e.prim)];
  const auto rgb = ShadingUnit::shade(s, hs.lighting, cfg, x - s.x0, y - s.y0, e.depth, e.cap, ovf);
  for (int c = 0; c < 3; ++c) fb.color.data[pix * 3 + c] = rgb[std::size_t(c)];
  fb.depth[pix] = (double(e.z) + 0.5) * std::ldexp(1.0, -cfg.zbuffer_bits);
  fb.object[pix] = s.object;
  fb.primitive[pix] = e.prim;
}

void ZBufferState::clear() { std::fill(px.begin(), px.end(), ZEntry{}); }

FrameBuffer resolveFrame(const Scene& scene, const HwConfig& cfg, const HwSceneSetup& hs, const ZBufferState& zb,
                         int threads, HwStats& stats) {
  FrameBuffer fb(scene.width, scene.height, toSrgb8(scene.background));
  const int nt = threads > 0 ? threads : omp_get_max_threads();
  std::uint64_t distinct = 0;
#pragma omp parallel for schedule(dynamic, 8) num_threads(nt) reduction(+ : distinct)
  for (int y = 0; y < scene.height; ++y) {
    OverflowCounter local;
    for (int x = 0; x < scene.width; ++x) {
      const std::size_t pix = std::size_t(y) * scene.width + x;
      if (zb.px[pix].prim < 0) continue;
      resolvePixel(cfg, hs, x, y, zb.px[pix], fb, local);
      ++distinct;
    }
  }
  stats.distinct_written = distinct;
  return fb;
}

}  // namespace qacc
