// CsgIntervalList: the bounded per-pixel list of the accelerator's CSG path (docs/CSG.md,
// engines/csg_tile.h). A pixel's list holds at most cfg.csg_list_depth intervals of the
// csg object's leaves along its line, kept in increasing entry depth (an arriving interval
// is inserted after the ones with an equal or nearer entry). When the list is full the
// hardware keeps the nearest intervals: an arriving interval whose entry is nearer than
// the last one's replaces it, any other is dropped; either way the pixel is marked
// overflowed (counted in the statistics and the accuracy line: its image may be wrong).
// Whole intervals are kept or dropped, so every kept entry has its exit and the sweep's
// inside/outside counters balance.
//
// Storage per pixel (the list memory of one 32x32 tile, priced by the cost model): a
// count of ceil(log2(depth + 1)) bits, an overflow flag, and per interval two depths of
// the internal format (depth_bits), the leaf index (csg_leaf_bits) and two end tags
// (csg_tag_bits each: surface, near/far plane, or one of the leaf's clip planes).
#pragma once
#include <cstdint>
#include <vector>

#include "hw_model/config/hw_config.h"

namespace qacc {

struct CsgListInterval {
  std::int64_t zin = 0, zout = 0;  // internal depth format
  int leaf = 0;                    // index of the leaf in its tree (CsgPixelTree::leafPrimitive)
  int tagIn = 0, tagOut = 0;       // DepthBound tags
};

class CsgIntervalList {
 public:
  void clear() {
    items_.clear();
    overflowed_ = false;
  }
  // Returns false when an interval was dropped (this one or the farthest kept one).
  bool insert(const CsgListInterval& iv, int depth);
  const std::vector<CsgListInterval>& intervals() const { return items_; }
  bool overflowed() const { return overflowed_; }

 private:
  std::vector<CsgListInterval> items_;
  bool overflowed_ = false;
};

// The number of tile list buffers: the list memory holds two tiles' lists, so that the
// pipelines fill one while the sweep unit reads the other (hw-cycle's CSG pass).
constexpr int kCsgListBuffers = 2;

// Bits of one pixel's list, and of its count field.
int csgListCountBits(const HwConfig& cfg);
int csgListBitsPerPixel(const HwConfig& cfg);

}  // namespace qacc
