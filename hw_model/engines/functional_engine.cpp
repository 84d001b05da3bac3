#include "hw_model/engines/functional_engine.h"

#include <omp.h>

#include <algorithm>
#include <chrono>

#include "hw_model/datapath/depth_roots.h"
#include "hw_model/engines/frame_setup.h"
#include "hw_model/datapath/pixel_datapath.h"
#include "hw_model/timing/traversal_unit.h"
#include "hw_model/timing/zbuffer_unit.h"
#include "raster/pixel/shading.h"

namespace qacc {

namespace {
constexpr int kTile = 32;
}

HwRender renderHw(const Scene& scene, const HwConfig& cfg, int threads) {
  const auto t0 = std::chrono::steady_clock::now();
  const int W = scene.width, H = scene.height;
  const int nt = threads > 0 ? threads : omp_get_max_threads();
  HwRender out;
  HwStats& st = out.stats;
  st.describeRun("hw", cfg, scene.name, W, H, nt);

  const HwSceneSetup hs = HwSceneSetup::build(scene, cfg, nt);
  st.overflow.add(hs.overflow);
  st.primitives = hs.setups.size();
  const int tx = (W + kTile - 1) / kTile, ty = (H + kTile - 1) / kTile;
  std::vector<std::vector<int>> bins(std::size_t(tx) * std::size_t(ty));
  for (const PrimitiveSetup& s : hs.setups) {
    if (!s.visible) continue;
    ++st.visible_primitives;
    st.facet_primitives += s.facet;
    for (int j = s.y0 / kTile; j <= (s.y1 - 1) / kTile; ++j)
      for (int i = s.x0 / kTile; i <= (s.x1 - 1) / kTile; ++i) bins[std::size_t(j) * tx + i].push_back(s.index);
  }

  // Each tile has its own Z-buffer (a tile-sized ZBufferState per thread, reused), so the
  // frame's depth state never exists as a whole: the tile's winners are shaded into the
  // frame buffer as soon as its last primitive is drawn.
  FrameBuffer fb(W, H, toSrgb8(scene.background));
  const int ntiles = tx * ty;
  std::vector<PixelCounters> pc(static_cast<std::size_t>(ntiles));
  std::vector<OverflowCounters> oc(static_cast<std::size_t>(ntiles));
  std::uint64_t distinct = 0;
#pragma omp parallel num_threads(nt) reduction(+ : distinct)
  {
    ZBufferState zb(kTile, kTile);
#pragma omp for schedule(dynamic, 1)
    for (int t = 0; t < ntiles; ++t) {
      const int tx0 = (t % tx) * kTile, ty0 = (t / tx) * kTile;
      const int tx1 = std::min(W, tx0 + kTile), ty1 = std::min(H, ty0 + kTile);
      PixelCounters& px = pc[std::size_t(t)];
      OverflowCounters& ovf = oc[std::size_t(t)];
      const std::vector<int>& bin = bins[std::size_t(t)];
      if (bin.empty()) continue;
      zb.clear();
      for (int k : bin) {
        const PrimitiveSetup& s = hs.setups[std::size_t(k)];
        PixelPipeline pp(s, cfg);
        for (int y = std::max(ty0, s.y0); y < std::min(ty1, s.y1); ++y) {
          Span sp[2];
          const int n = TraversalUnit::spans(s, y, tx0, tx1, sp);
          for (int i = 0; i < n; ++i) {
            pp.startSpan(sp[i].x0 - s.x0, y - s.y0);
            for (int x = sp[i].x0; x < sp[i].x1; ++x) {
              ++px.tested;
              const PixelOutcome o = pp.evaluate(ovf);
              pp.stepRight();
              px.clip_passes += std::uint64_t(o.clipPasses);
              if (!o.hit) {
                px.clipped += o.candidate;
                continue;
              }
              ++px.covered;
              px.caps += o.cap >= 0;
              const std::size_t pix = std::size_t(y - ty0) * kTile + std::size_t(x - tx0);
              if (ZBufferUnit::testAndWrite(zb, pix, DepthUnit::zbufferValue(o.z, cfg), k, o.z, o.cap))
                ++px.written;
              else
                ++px.depth_rejected;
            }
          }
        }
      }
      for (int y = ty0; y < ty1; ++y)
        for (int x = tx0; x < tx1; ++x) {
          const std::size_t pix = std::size_t(y - ty0) * kTile + std::size_t(x - tx0);
          if (zb.px[pix].prim < 0) continue;
          resolvePixel(cfg, hs, x, y, zb.px[pix], fb, ovf.shading);
          ++distinct;
        }
    }
  }
  for (int t = 0; t < ntiles; ++t) {
    st.pixels.add(pc[std::size_t(t)]);
    st.overflow.add(oc[std::size_t(t)]);
  }
  st.distinct_written = distinct;
  out.fb = std::move(fb);
  st.host_seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
  return out;
}

}  // namespace qacc
