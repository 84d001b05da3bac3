#include "hw_model/engines/csg_tile.h"

#include <algorithm>
#include <cmath>

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
                 int tileIndex, ZBufferMemory& zb, int zbWidth, PixelCounters& px, OverflowCounters& ovf,
                 CsgCounters& cc) {
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
      const std::size_t pix = std::size_t(y - tile.y0) * std::size_t(zbWidth) + std::size_t(x - tile.x0);
      if (zb.testAndWrite(pix, ZBufferMemory::storedValue(z, cfg), h.primitive, z, h.cap))
        ++px.written;
      else
        ++px.depth_rejected;
    }
}

}  // namespace qacc
