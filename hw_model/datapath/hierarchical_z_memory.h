// HierarchicalZMemory: the tile memory of the optional hierarchical Z unit (HwConfig::
// hierarchical_z, docs/HW_MODEL.md "Hierarchical Z"): per screen tile of hiz_tile_size²
// pixels, a conservative bound on the largest stored depth of the tile, and the rejection
// test of a block of a span against it. No time here (the unit's timing is
// timing/hierarchical_z_unit.h).
//
// The bound without reading the tile (a masked two-layer maximum, as in Andersson,
// Hasselgren and Akenine-Möller's "Masked depth culling", HPG 2015, with the mask kept as
// one bit per pixel in the Z-buffer's own record, which the Z unit reads and writes anyway):
// per tile, zmax0, the current bound; zmax1, the largest value written since the current
// layer began; count, how many of the tile's pixels were written since; and parity, the
// layer's bit. A pixel whose layer bit differs from the tile's parity joins the layer
// (count + 1). Invariants: a pixel not in the layer holds a stored depth <= zmax0 (it was
// not written since zmax0 was set, or zmax0 is "far": nothing is known yet); a pixel in the
// layer holds its last write, <= zmax1. When every pixel of the tile is in the layer, the
// whole tile is <= zmax1: zmax0 takes it and a new layer begins (parity flips, count 0).
// Stored depths only move nearer (the Z test is strict), so a bound stays true until it is
// lowered, and a write the memory does not see (the CSG pass) only makes it looser.
//
// The maxima are kept in hiz_depth_bits (at most zbuffer_bits): a stored value v is held as
// v >> s (s = zbuffer_bits − bits), standing for every value up to ((v >> s) + 1) 2^s − 1.
//
// Rejection (ties included): the Z test passes a pixel only when its stored value is strictly
// below the buffer's (ZBufferMemory::testAndWrite). A primitive's depth floor F (the depth
// unit never returns less, PrimitiveSetup::zFloor) stores as storedValue(F) <= storedValue(z)
// for each of its pixels (storedValue is monotone). If storedValue(F) >= bound(tile) >= every
// stored value of the tile now, and stored values only fall, each pixel's Z test will find
// storedValue(z) >= stored: it fails. So the rejected pixels are exactly pixels that would
// fail the Z test; images cannot change.
#pragma once
#include <cstdint>
#include <vector>

#include "hw_model/config/hw_config.h"

namespace qacc {

class HierarchicalZMemory {
 public:
  static constexpr std::uint32_t kFar = 0xFFFFFFFFu;  // nothing known: no rejection
  struct Tile {
    std::uint32_t zmax0 = kFar;  // coarse units; kFar until the tile was once fully written
    std::uint32_t zmax1 = 0;     // coarse units
    std::uint32_t count = 0;     // pixels written in the current layer
    std::uint8_t parity = 1;     // the pixels' layer bits start at 0: outside the first layer
  };

  // A memory for the pixels [x0, x0 + width) x [y0, y0 + height) of the screen (the whole
  // screen for hw-cycle, one 32x32 traversal tile for hw); tiles are aligned to the screen.
  HierarchicalZMemory(const HwConfig& cfg, int x0, int y0, int width, int height);
  void clear();  // every tile back to "far", every pixel outside the layer
  int tileSize() const { return size_; }
  // The tile holding screen pixel (x, y).
  int tileOf(int x, int y) const { return ((y - y0_) >> shift_) * tilesX_ + ((x - x0_) >> shift_); }
  // True when every pixel of `tile` already stores a value <= the bound and storedFloor is
  // not below it: a block of a span in that tile with that floor fails the Z test everywhere.
  bool rejects(int tile, std::uint32_t storedFloor) const {
    const std::uint32_t m = tiles_[std::size_t(tile)].zmax0;
    if (m == kFar) return false;
    const std::uint64_t bound = ((std::uint64_t(m) + 1) << coarseShift_) - 1;
    return std::uint64_t(storedFloor) >= bound;
  }
  // A write of stored value `stored` to screen pixel (x, y) (a pixel that passed the Z test).
  void write(int x, int y, std::uint32_t stored);
  // The bits of the memory: per tile two maxima, the count and the parity (on chip); the
  // layer bit of each pixel lives in the Z-buffer's record (off chip).
  static int bitsPerTile(const HwConfig& cfg);
  static int depthBits(const HwConfig& cfg);

 private:
  int x0_, y0_, width_;
  int size_, shift_, tilesX_, tilesY_, coarseShift_;
  std::vector<Tile> tiles_;
  std::vector<std::uint32_t> tilePixels_;  // pixels of each tile inside the region
  std::vector<std::uint8_t> layer_;        // per pixel: the layer bit
};

}  // namespace qacc
