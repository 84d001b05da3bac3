// The accelerator's CSG path (docs/CSG.md): bounded per-pixel interval lists. For a `csg`
// object in one screen tile, the tree is pruned by the leaves whose boxes touch the tile
// (csg_tile_pruning, modeling/csg/csg_tree_pruning.h; off: the whole tree), every leaf of
// the pruned tree whose box touches the tile runs through the pixel
// datapath in interval mode (PixelDatapath::solidIntervals) over its box ∩ tile, and its
// intervals are inserted into the pixel's list (datapath/csg_interval_list.h: at most
// csg_list_depth intervals, the nearest kept on overflow, the pixel counted); the tree is
// then evaluated per pixel (on the pruned tree) by the same sweep as the reference (raster/reference/csg_hit.h)
// on the fixed-point depths, ends within kCsgEndTolerance LSBs counting as one event, and
// the winning boundary goes through the ordinary Z test with its leaf as the primitive.
// Datapath only, no time: `hw-cycle` times the same work from a CsgJob record
// (engines/csg_cycle_pass.h).
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

// Depth LSBs (2^-28 each at the default format): 16 is one LSB of a 24-bit Z-buffer. With
// 4, a turned notched cube whose shared faces reach a pixel's line through different
// arithmetic (a slab quadric's root, a clip plane) kept a sliver of the cube at 4 pixels
// near the notch's corner (CsgEngine.CoincidentFacesLeaveNoSpecklesInHw); 8 was the
// smallest that cleared it; 4096 merged real events (pinholes).
constexpr int kCsgEndTolerance = 16;

// The window-space leaves and the per-pixel trees of a scene's csg objects (not movable:
// the trees point at `win`). Refuses (SceneError, file and JSON path of the csg object) a
// tree the list entries cannot address: more leaves than 2^csg_leaf_bits, or a leaf with
// more clip planes than csg_tag_bits can tag.
struct CsgFrame {
  CsgFrame(const Scene& scene, const HwConfig& cfg, int width, int height);
  CsgFrame(const CsgFrame&) = delete;
  CsgFrame& operator=(const CsgFrame&) = delete;
  // The csg object of primitive i, -1 for a primitive outside every csg object.
  int treeOf(std::size_t i) const { return treeOfPrimitive.empty() ? -1 : treeOfPrimitive[i]; }
  // Without csg objects the frame holds nothing (no per-primitive window forms or tree
  // indices are made): a scene pays for the CSG path only when it uses it.
  std::vector<WindowPrimitive> win;
  std::vector<CsgPixelTree> trees;
  std::vector<int> treeOfPrimitive;  // empty without csg objects (treeOf)
};

// Where drawCsgTile writes: a Z-buffer whose pixel (x, y) is at (y - y0) * width + x - x0,
// and the rule for equal stored depths. `hw` draws a csg object in scene order among the
// other primitives (strict test: the earlier one stays).
struct CsgTarget {
  ZBufferMemory& zb;
  int x0 = 0, y0 = 0, width = 0;
};

// The work of one csg object in one tile, in the order the hardware does it, for the
// timed units of hw-cycle: the (leaf, pixel) evaluations as issued, then every pixel
// with a non-empty list with the ends its sweep reads and its winner (prim -1: none).
struct CsgLeafPixel {
  int x = 0, y = 0;
  int intervals = 0;   // intervals the datapath produced (0..2), each one list insertion
  int clipPasses = 1;  // clip-unit passes (a leaf with more planes than clip_evaluators)
};
struct CsgSweptPixel {
  int x = 0, y = 0;
  int ends = 0;  // list ends read by the sweep (2 per kept interval)
  int prim = -1, cap = -1;
  i128 z = 0;
};
struct CsgJob {
  int tile = 0, tree = 0;
  // Tile pruning (csg_tile_pruning): the cycles of the box tester before the job issues
  // (one per node of the tree: a leaf's box compared with the tile, or an inner node's
  // emptiness from its operands'), and whether the pruned tree is empty in the tile (the
  // job then ends after its tests: no list buffer, nothing issued or swept).
  int testCycles = 0;
  bool pruned = false;
  std::vector<CsgLeafPixel> issued;
  std::vector<CsgSweptPixel> swept;
};

// Draws CSG tree `tree` on the pixels of tile `tileIndex` (pixels `tile`) into `target`
// (Z test and counters `px`), or, with target null, records the winners in `job`; `job`
// (when not null) also receives the issued leaf pixels.
void drawCsgTile(const CsgPixelTree& tree, const FrameSetup& fs, const HwConfig& cfg, const ScreenBox& tile,
                 int tileIndex, const CsgTarget* target, PixelCounters& px, OverflowCounters& ovf, CsgCounters& cc,
                 CsgJob* job = nullptr);

}  // namespace qacc
