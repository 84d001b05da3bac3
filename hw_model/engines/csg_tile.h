// The accelerator's CSG path (docs/CSG.md): per-pixel interval lists. For a `csg` object
// in one screen tile, every leaf whose box touches the tile runs through the pixel
// datapath in interval mode (PixelDatapath::solidIntervals) over its box ∩ tile, and its
// interval ends are appended to the pixel's list; the tree is then evaluated per pixel by
// the same sweep as the reference (raster/reference/csg_hit.h) on the fixed-point depths,
// ends within kCsgEndTolerance LSBs counting as one event, and the winning boundary goes
// through the ordinary Z test with its leaf as the primitive. Datapath only, no time.
#pragma once
#include <cstdint>
#include <vector>

#include "hw_model/config/hw_config.h"
#include "hw_model/datapath/overflow_counters.h"
#include "hw_model/datapath/zbuffer_memory.h"
#include "hw_model/engines/frame_setup.h"
#include "hw_model/report/hw_stats.h"
#include "raster/reference/csg_hit.h"

namespace qacc {

constexpr int kCsgEndTolerance = 4;  // depth LSBs

// The window-space leaves and the per-pixel trees of a scene's csg objects (not movable:
// the trees point at `win`).
struct CsgFrame {
  CsgFrame(const Scene& scene, int width, int height);
  CsgFrame(const CsgFrame&) = delete;
  CsgFrame& operator=(const CsgFrame&) = delete;
  std::vector<WindowPrimitive> win;
  std::vector<CsgPixelTree> trees;
  std::vector<int> treeOfPrimitive;  // -1 for primitives outside every csg object
};

// Where drawCsgTile writes: a Z-buffer whose pixel (x, y) is at (y - y0) * width + x - x0,
// and the rule for equal stored depths. `hw` draws a csg object in scene order among the
// other primitives (strict test: the earlier one stays); `hw-cycle` draws it after its
// timed loop, so an equal depth goes to the primitive earlier in scene order (a csg
// object's leaves are contiguous in the scene, so their indices stand for its place).
struct CsgTarget {
  ZBufferMemory& zb;
  int x0 = 0, y0 = 0, width = 0;
  bool afterOthers = false;
};

// Draws CSG tree `tree` on the pixels of tile `tileIndex` (pixels `tile`).
void drawCsgTile(const CsgPixelTree& tree, const FrameSetup& fs, const HwConfig& cfg, const ScreenBox& tile,
                 int tileIndex, const CsgTarget& target, PixelCounters& px, OverflowCounters& ovf, CsgCounters& cc);
// Draws every csg object of the frame after the other primitives into a frame-sized
// Z-buffer (hw-cycle), tiles in parallel; the result equals drawing them in scene order.
void drawCsgFrame(const CsgFrame& csg, const FrameSetup& fs, const HwConfig& cfg, int width, int height,
                  ZBufferMemory& zb, int threads, HwStats& stats);

}  // namespace qacc
