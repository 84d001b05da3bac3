#include "hw_model/engines/functional_engine.h"

#include <omp.h>

#include <algorithm>
#include <atomic>
#include <chrono>
#include <optional>

#include "hw_model/datapath/hierarchical_z_memory.h"
#include "hw_model/datapath/pixel_datapath.h"
#include "hw_model/datapath/span_solver.h"
#include "hw_model/datapath/zbuffer_memory.h"
#include "hw_model/engines/csg_tile.h"
#include "hw_model/engines/frame_resolve.h"
#include "hw_model/engines/frame_setup.h"
#include "raster/pixel/shading.h"
#include "raster/pixel/tile_binner.h"

namespace qacc {

HwRender renderHw(const Scene& scene, const HwConfig& cfg, int threads) {
  const auto t0 = std::chrono::steady_clock::now();
  const int W = scene.width, H = scene.height;
  const int nt = threads > 0 ? threads : omp_get_max_threads();
  HwRender out;
  HwStats& st = out.stats;
  st.describeRun("hw", cfg, scene.name, W, H, nt);
  st.priceNeeds(scene);

  const FrameSetup fs = FrameSetup::build(scene, cfg, nt);
  st.overflow.add(fs.overflow);
  st.primitives = fs.setups.size();
  TileBinner bins(W, H);
  // A csg object is one item (index -1 - tree) in the place of its leaves (csg_tile.h).
  const CsgFrame csg(scene, cfg, W, H);
  std::vector<bool> csgAdded(csg.trees.size(), false);
  st.csg.objects = csg.trees.size();
  for (const PrimitiveSetup& s : fs.setups) {
    const int tree = csg.treeOf(std::size_t(s.index));
    if (tree >= 0 && !csgAdded[std::size_t(tree)]) {
      csgAdded[std::size_t(tree)] = true;
      bins.add(-1 - tree, csg.trees[std::size_t(tree)].box());
    }
    st.culled_at_host += s.culled;
    if (!s.visible) continue;
    ++st.visible_primitives;
    st.facet_primitives += s.facet;
    if (tree < 0) bins.add(s.index, {s.x0, s.y0, s.x1, s.y1});
  }

  // Each tile has its own Z-buffer (a tile-sized ZBufferMemory per thread, reused), so the
  // frame's depth state never exists as a whole: the tile's winners are shaded into the
  // frame buffer as soon as its last primitive is drawn.
  constexpr int kTile = TileBinner::kTileSize;
  // The frame buffer is not cleared up front: each tile writes each of its pixels once (in
  // parallel, first touching its pages), its winners shaded and the rest the background.
  const FrameBuffer::Background background(toSrgb8(scene.background));
  FrameBuffer fb = FrameBuffer::uninitialised(W, H);
  const int ntiles = bins.tiles();
  std::vector<PixelCounters> pc(static_cast<std::size_t>(ntiles));
  std::vector<OverflowCounters> oc(static_cast<std::size_t>(ntiles));
  std::vector<CsgCounters> cc(static_cast<std::size_t>(ntiles));
  // The hierarchical Z unit (datapath/hierarchical_z_memory.h): a tile memory per traversal
  // tile, each primitive's stored depth floor, and whether a block of a primitive was looked
  // up / accepted in any tile (for the primitives rejected whole).
  const bool useHiz = cfg.hierarchical_z;
  std::vector<HierarchicalZCounters> hc(useHiz ? std::size_t(ntiles) : 0);
  std::vector<std::uint32_t> storedFloors;
  std::vector<std::atomic<std::uint8_t>> hizSeen(useHiz ? fs.setups.size() : 0);
  if (useHiz)
    for (const PrimitiveSetup& s : fs.setups) storedFloors.push_back(ZBufferMemory::storedValue(s.zFloor, cfg));
  std::uint64_t distinct = 0;
#pragma omp parallel num_threads(nt) reduction(+ : distinct)
  {
    ZBufferMemory zb(kTile, kTile);
    // One pixel datapath per thread, loaded with each (primitive, tile) in turn, and the
    // outcomes of one span (at most a tile wide) before its Z tests.
    PixelDatapath pp(cfg);
    PixelOutcome outcomes[kTile];
#pragma omp for schedule(dynamic, 1)
    for (int t = 0; t < ntiles; ++t) {
      const ScreenBox tile = bins.tile(t);
      const int tx0 = tile.x0, ty0 = tile.y0, tx1 = tile.x1, ty1 = tile.y1;
      PixelCounters& px = pc[std::size_t(t)];
      OverflowCounters& ovf = oc[std::size_t(t)];
      const std::vector<int>& bin = bins.bin(t);
      if (bin.empty()) {
        fb.clearRect(tx0, ty0, tx1, ty1, background);
        continue;
      }
      zb.clear();
      std::optional<HierarchicalZMemory> hiz;
      if (useHiz) hiz.emplace(cfg, tx0, ty0, tx1 - tx0, ty1 - ty0);
      for (int k : bin) {
        if (k < 0) {
          const CsgTarget target{zb, tx0, ty0, kTile};
          drawCsgTile(csg.trees[std::size_t(-1 - k)], fs, cfg, tile, t, &target, px, ovf, cc[std::size_t(t)]);
          continue;
        }
        const PrimitiveSetup& s = fs.setups[std::size_t(k)];
        pp.load(s);
        // The pixels [xa, xb) of row y (within the tile), through the pipelines and the Z test.
        const auto draw = [&](int y, int xa, int xb) {
          pp.evaluateSpan(xa - s.x0, y - s.y0, xb - xa, outcomes, ovf);
          for (int x = xa; x < xb; ++x) {
            ++px.tested;
            const PixelOutcome& o = outcomes[x - xa];
            px.clip_passes += std::uint64_t(o.clipPasses);
            if (!o.hit) {
              px.clipped += o.candidate;
              continue;
            }
            ++px.covered;
            px.caps += o.cap >= 0;
            const std::size_t pix = std::size_t(y - ty0) * kTile + std::size_t(x - tx0);
            const std::uint32_t stored = ZBufferMemory::storedValue(o.z, cfg);
            if (zb.testAndWrite(pix, stored, k, o.z, o.cap)) {
              ++px.written;
              if (hiz) hiz->write(x, y, stored);
            } else {
              ++px.depth_rejected;
            }
          }
        };
        bool accepted = false, looked = false;
        for (int y = std::max(ty0, s.y0); y < std::min(ty1, s.y1); ++y) {
          Span sp[2];
          const int n = solveSpans(s, y, tx0, tx1, sp);
          for (int i = 0; i < n; ++i) {
            if (!hiz) {
              draw(y, sp[i].x0, sp[i].x1);
              continue;
            }
            // Block by block (a span's pixels in one hierarchical Z tile): a rejected block
            // would fail the Z test everywhere and is skipped.
            HierarchicalZCounters& h = hc[std::size_t(t)];
            const int T = hiz->tileSize();
            for (int xa = sp[i].x0; xa < sp[i].x1;) {
              const int xb = std::min(sp[i].x1, (xa / T + 1) * T);
              ++h.blocks_tested;
              looked = true;
              if (hiz->rejects(hiz->tileOf(xa, y), storedFloors[std::size_t(k)])) {
                ++h.blocks_rejected;
                h.pixels_rejected += std::uint64_t(xb - xa);
              } else {
                accepted = true;
                draw(y, xa, xb);
              }
              xa = xb;
            }
          }
        }
        // Bit 1: a block was looked up, bit 2: a block was accepted (in any tile).
        if (looked) hizSeen[std::size_t(k)].fetch_or(std::uint8_t(1 | (accepted ? 2 : 0)), std::memory_order_relaxed);
      }
      for (int y = ty0; y < ty1; ++y)
        distinct += resolveRow(cfg, fs, tx0, tx1, y, &zb.px[std::size_t(y - ty0) * kTile], background, fb, ovf.shading);
    }
  }
  for (int t = 0; t < ntiles; ++t) {
    st.pixels.add(pc[std::size_t(t)]);
    st.overflow.add(oc[std::size_t(t)]);
    st.csg.add(cc[std::size_t(t)]);
  }
  if (useHiz) {
    st.hiz.enabled = true;
    for (const HierarchicalZCounters& h : hc) st.hiz.add(h);
    for (const auto& f : hizSeen) {
      const std::uint8_t v = f.load(std::memory_order_relaxed);
      st.hiz.primitives_tested += (v & 1) != 0;
      st.hiz.primitives_rejected += v == 1;
    }
  }
  st.distinct_written = distinct;
  out.fb = std::move(fb);
  st.host_seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
  return out;
}

}  // namespace qacc
