#include "hw_model/engines/csg_tile.h"

#include <algorithm>
#include <cmath>

#include <omp.h>

#include "hw_model/datapath/pixel_datapath.h"

namespace qacc {

CsgFrame::CsgFrame(const Scene& scene, int width, int height)
    : win(scene.primitives.size()), treeOfPrimitive(scene.primitives.size(), -1) {
  const Eigen::Matrix4d Minv = scene.camera.worldToWindow(width, height).inverse();
  trees.reserve(scene.csg_trees.size());
  for (std::size_t t = 0; t < scene.csg_trees.size(); ++t)
    for (int p : scene.csg_trees[t].leafPrimitives()) {
      win[std::size_t(p)] = toWindow(scene.primitives[std::size_t(p)], p, Minv, width, height);
      treeOfPrimitive[std::size_t(p)] = int(t);
    }
  for (const CsgTree& t : scene.csg_trees) trees.emplace_back(t, win, width, height);
}

void drawCsgTile(const CsgPixelTree& tree, const FrameSetup& fs, const HwConfig& cfg, const ScreenBox& tile,
                 int tileIndex, const CsgTarget& target, PixelCounters& px, OverflowCounters& ovf, CsgCounters& cc) {
  const int tw = tile.x1 - tile.x0, th = tile.y1 - tile.y0;
  const double unit = std::ldexp(1.0, -cfg.depth_frac_bits);
  thread_local std::vector<std::vector<CsgPixelTree::Boundary>> lists;
  lists.resize(std::size_t(tw) * std::size_t(th));
  for (auto& l : lists) l.clear();
  for (int leaf : tree.leavesInTile(tileIndex)) {
    const PrimitiveSetup& s = fs.setups[std::size_t(tree.leafPrimitive(leaf))];
    if (!s.visible || s.facet) continue;
    PixelDatapath dp(s, cfg);
    const int x0 = std::max(tile.x0, s.x0), x1 = std::min(tile.x1, s.x1);
    for (int y = std::max(tile.y0, s.y0); y < std::min(tile.y1, s.y1); ++y) {
      if (x0 >= x1) break;
      dp.startSpan(x0 - s.x0, y - s.y0);
      for (int x = x0; x < x1; ++x, dp.stepRight()) {
        ++cc.leaf_pixels;
        FixedDepthInterval iv[2];
        const int n = dp.solidIntervals(ovf, iv);
        auto& list = lists[std::size_t(y - tile.y0) * std::size_t(tw) + std::size_t(x - tile.x0)];
        for (int k = 0; k < n; ++k) {
          list.push_back({double(iv[k].in.z) * unit, leaf, true, iv[k].in.tag});
          list.push_back({double(iv[k].out.z) * unit, leaf, false, iv[k].out.tag});
        }
      }
    }
  }
  const double tolerance = kCsgEndTolerance * unit;
  for (int y = tile.y0; y < tile.y1; ++y)
    for (int x = tile.x0; x < tile.x1; ++x) {
      auto& list = lists[std::size_t(y - tile.y0) * std::size_t(tw) + std::size_t(x - tile.x0)];
      if (list.empty()) continue;
      cc.interval_ends += list.size();
      cc.max_list_ends = std::max<std::uint64_t>(cc.max_list_ends, list.size());
      ++cc.resolved;
      CsgHit h;
      if (!tree.resolve(list, tolerance, h)) continue;
      // The depth came from the fixed-point format, so this is exact.
      const i128 z = i128(std::llround(h.z / unit));
      ++px.covered;
      px.caps += h.cap >= 0;
      const std::size_t pix = std::size_t(y - target.y0) * std::size_t(target.width) + std::size_t(x - target.x0);
      const std::uint32_t stored = ZBufferMemory::storedValue(z, cfg);
      ZEntry& e = target.zb.px[pix];
      const bool wins = stored < e.z || (target.afterOthers && stored == e.z && h.primitive < e.prim);
      if (wins) {
        e = {std::int64_t(z), stored, h.primitive, std::int16_t(h.cap)};
        ++px.written;
      } else {
        ++px.depth_rejected;
      }
    }
}

void drawCsgFrame(const CsgFrame& csg, const FrameSetup& fs, const HwConfig& cfg, int width, int height,
                  ZBufferMemory& zb, int threads, HwStats& stats) {
  stats.csg.objects = csg.trees.size();
  if (csg.trees.empty()) return;
  TileBinner bins(width, height);
  const CsgTarget target{zb, 0, 0, width, true};
  std::vector<PixelCounters> pc(std::size_t(bins.tiles()));
  std::vector<OverflowCounters> oc(std::size_t(bins.tiles()));
  std::vector<CsgCounters> cc(std::size_t(bins.tiles()));
#pragma omp parallel for schedule(dynamic, 1) num_threads(threads)
  for (int t = 0; t < bins.tiles(); ++t) {
    const ScreenBox tile = bins.tile(t);
    for (const CsgPixelTree& tree : csg.trees)
      if (!tree.box().intersect(tile).empty())
        drawCsgTile(tree, fs, cfg, tile, t, target, pc[std::size_t(t)], oc[std::size_t(t)], cc[std::size_t(t)]);
  }
  for (int t = 0; t < bins.tiles(); ++t) {
    stats.overflow.add(oc[std::size_t(t)]);
    stats.csg.add(cc[std::size_t(t)]);
  }
}

}  // namespace qacc
