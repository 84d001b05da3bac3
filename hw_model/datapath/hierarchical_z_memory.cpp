#include "hw_model/datapath/hierarchical_z_memory.h"

#include <algorithm>

namespace qacc {

int HierarchicalZMemory::depthBits(const HwConfig& cfg) { return std::min(cfg.hiz_depth_bits, cfg.zbuffer_bits); }

int HierarchicalZMemory::bitsPerTile(const HwConfig& cfg) {
  int countBits = 1;
  while ((1 << countBits) <= cfg.hiz_tile_size * cfg.hiz_tile_size) ++countBits;
  return 2 * depthBits(cfg) + 1 + countBits + 1;  // zmax0, its "far" flag, zmax1, count, parity
}

HierarchicalZMemory::HierarchicalZMemory(const HwConfig& cfg, int x0, int y0, int width, int height)
    : x0_(x0), y0_(y0), width_(width), size_(cfg.hiz_tile_size) {
  shift_ = 0;
  while ((1 << shift_) < size_) ++shift_;
  tilesX_ = (width + size_ - 1) / size_;
  tilesY_ = (height + size_ - 1) / size_;
  coarseShift_ = cfg.zbuffer_bits - depthBits(cfg);
  tiles_.resize(std::size_t(tilesX_) * std::size_t(tilesY_));
  tilePixels_.resize(tiles_.size());
  for (int ty = 0; ty < tilesY_; ++ty)
    for (int tx = 0; tx < tilesX_; ++tx)
      tilePixels_[std::size_t(ty * tilesX_ + tx)] =
          std::uint32_t(std::min(size_, width - tx * size_) * std::min(size_, height - ty * size_));
  layer_.assign(std::size_t(width) * std::size_t(height), 0);
}

void HierarchicalZMemory::clear() {
  std::fill(tiles_.begin(), tiles_.end(), Tile{});
  std::fill(layer_.begin(), layer_.end(), std::uint8_t(0));
}

void HierarchicalZMemory::write(int x, int y, std::uint32_t stored) {
  const int t = tileOf(x, y);
  Tile& tile = tiles_[std::size_t(t)];
  const std::uint32_t coarse = stored >> coarseShift_;
  std::uint8_t& bit = layer_[std::size_t(y - y0_) * std::size_t(width_) + std::size_t(x - x0_)];
  if (bit != tile.parity) {
    bit = tile.parity;
    ++tile.count;
  }
  tile.zmax1 = std::max(tile.zmax1, coarse);
  if (tile.count == tilePixels_[std::size_t(t)]) {  // the whole tile is in the layer: <= zmax1
    tile.zmax0 = tile.zmax1;
    tile.zmax1 = 0;
    tile.count = 0;
    tile.parity ^= 1;
  }
}

}  // namespace qacc
