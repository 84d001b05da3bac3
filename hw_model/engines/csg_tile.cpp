#include "hw_model/engines/csg_tile.h"

#include <algorithm>
#include <cmath>
#include <string>
#include <utility>

#include "hw_model/datapath/clip_test.h"
#include "hw_model/datapath/csg_interval_list.h"
#include "hw_model/datapath/pixel_datapath.h"
#include "modeling/csg/csg_tree_pruning.h"
#include "modeling/scene/scene_error.h"

namespace qacc {

CsgFrame::CsgFrame(const Scene& scene, const HwConfig& cfg, int width, int height) {
  if (scene.csg_trees.empty()) return;
  win.resize(scene.primitives.size());
  treeOfPrimitive.assign(scene.primitives.size(), -1);
  const Eigen::Matrix4d M = scene.camera.worldToWindow(width, height), Minv = M.inverse();
  trees.reserve(scene.csg_trees.size());
  const long long maxLeaves = 1LL << cfg.csg_leaf_bits;
  const std::size_t maxPlanes = (std::size_t(1) << cfg.csg_tag_bits) - 2;
  for (std::size_t t = 0; t < scene.csg_trees.size(); ++t) {
    const std::vector<int> leaves = scene.csg_trees[t].leafPrimitives();
    const std::string where = "/objects/" + std::to_string(scene.csg_trees[t].object);
    if (static_cast<long long>(leaves.size()) > maxLeaves)
      throw SceneError(scene.file, where,
                       "csg object with " + std::to_string(leaves.size()) +
                           " leaves: the accelerator's interval lists address " + std::to_string(maxLeaves) +
                           " (csg_leaf_bits " + std::to_string(cfg.csg_leaf_bits) + ")");
    for (int p : leaves) {
      const Primitive& prim = scene.primitives[std::size_t(p)];
      if (prim.clip.size() > maxPlanes)
        throw SceneError(scene.file, where,
                         "a leaf with " + std::to_string(prim.clip.size()) +
                             " clip planes: the accelerator's list ends tag at most " + std::to_string(maxPlanes) +
                             " (csg_tag_bits " + std::to_string(cfg.csg_tag_bits) + ")");
      win[std::size_t(p)] = toWindow(prim, p, M, Minv, width, height);
      treeOfPrimitive[std::size_t(p)] = int(t);
    }
  }
  for (const CsgTree& t : scene.csg_trees) trees.emplace_back(t, win, width, height);
}

void drawCsgTile(const CsgPixelTree& tree, const FrameSetup& fs, const HwConfig& cfg, const ScreenBox& tile,
                 int tileIndex, const CsgTarget* target, PixelCounters& px, OverflowCounters& ovf, CsgCounters& cc,
                 CsgJob* job) {
  const int tw = tile.x1 - tile.x0, th = tile.y1 - tile.y0;
  const double unit = std::ldexp(1.0, -cfg.depth_frac_bits);
  thread_local std::vector<CsgIntervalList> lists;
  thread_local std::vector<std::uint32_t> offered;  // intervals that reached each pixel's list
  thread_local std::vector<CsgPixelTree::Boundary> ends;
  lists.resize(std::size_t(tw) * std::size_t(th));
  offered.assign(lists.size(), 0);
  for (auto& l : lists) l.clear();
  // Tile pruning: the leaves binned to the tile are the ones whose screen box touches it;
  // the tree pruned by them keeps the leaves still needed (csg_tree_pruning.h).
  thread_local std::vector<char> needed;
  const bool pruning = cfg.csg_tile_pruning;
  if (pruning) {
    thread_local std::vector<char> present;
    present.assign(tree.tree().nodes.size(), 0);
    for (int leaf : tree.leavesInTile(tileIndex)) present[std::size_t(tree.leafNode(leaf))] = 1;
    PrunedCsgTree pruned = pruneCsgTree(tree.tree(), present);
    needed = std::move(pruned.kept);
    cc.leaves_tested += std::uint64_t(tree.leafCount());
    cc.leaves_pruned += std::uint64_t(pruned.leavesPruned);
    cc.products_pruned += std::uint64_t(pruned.productsPruned);
    if (job) job->testCycles = int(tree.tree().nodes.size());
    if (pruned.tree.root < 0) {
      ++cc.jobs_pruned;
      if (job) job->pruned = true;
      return;
    }
  }
  for (int leaf : tree.leavesInTile(tileIndex)) {
    if (pruning && !needed[std::size_t(tree.leafNode(leaf))]) continue;
    const PrimitiveSetup& s = fs.setups[std::size_t(tree.leafPrimitive(leaf))];
    if (!s.visible || s.facet) continue;
    const int passes = ClipTest::passes(int(s.planes.size()), cfg.clip_evaluators);
    PixelDatapath dp(s, cfg);
    const int x0 = std::max(tile.x0, s.x0), x1 = std::min(tile.x1, s.x1);
    for (int y = std::max(tile.y0, s.y0); y < std::min(tile.y1, s.y1); ++y) {
      if (x0 >= x1) break;
      dp.startSpan(x0 - s.x0, y - s.y0);
      for (int x = x0; x < x1; ++x, dp.stepRight()) {
        ++cc.leaf_pixels;
        FixedDepthInterval iv[2];
        const int n = dp.solidIntervals(ovf, iv);
        if (job) job->issued.push_back({x, y, n, passes});
        const std::size_t pix = std::size_t(y - tile.y0) * std::size_t(tw) + std::size_t(x - tile.x0);
        offered[pix] += std::uint32_t(n);
        for (int k = 0; k < n; ++k)
          cc.dropped_intervals += !lists[pix].insert(
              {std::int64_t(iv[k].in.z), std::int64_t(iv[k].out.z), leaf, iv[k].in.tag, iv[k].out.tag},
              cfg.csg_list_depth);
      }
    }
  }
  const double tolerance = kCsgEndTolerance * unit;
  for (int y = tile.y0; y < tile.y1; ++y)
    for (int x = tile.x0; x < tile.x1; ++x) {
      const std::size_t pix = std::size_t(y - tile.y0) * std::size_t(tw) + std::size_t(x - tile.x0);
      const CsgIntervalList& list = lists[pix];
      if (list.intervals().empty()) continue;
      ends.clear();
      for (const CsgListInterval& iv : list.intervals()) {
        ends.push_back({double(iv.zin) * unit, iv.leaf, true, iv.tagIn});
        ends.push_back({double(iv.zout) * unit, iv.leaf, false, iv.tagOut});
      }
      cc.interval_ends += ends.size();
      cc.max_list_ends = std::max<std::uint64_t>(cc.max_list_ends, 2 * std::uint64_t(offered[pix]));
      cc.overflowed_pixels += list.overflowed();
      ++cc.resolved;
      CsgSweptPixel out{x, y, int(ends.size()), -1, -1, 0};
      CsgHit h;
      if (tree.resolve(ends, tolerance, h)) {
        // The depth came from the fixed-point format, so this is exact.
        out.z = i128(std::llround(h.z / unit));
        out.prim = h.primitive;
        out.cap = h.cap;
        ++px.covered;
        px.caps += h.cap >= 0;
        if (target) {
          const std::size_t t =
              std::size_t(y - target->y0) * std::size_t(target->width) + std::size_t(x - target->x0);
          if (target->zb.testAndWrite(t, ZBufferMemory::storedValue(out.z, cfg), out.prim, out.z, out.cap))
            ++px.written;
          else
            ++px.depth_rejected;
        }
      }
      if (job) job->swept.push_back(out);
    }
}

}  // namespace qacc
