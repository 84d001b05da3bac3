// TileBinner: the screen cut into kTileSize x kTileSize tiles and, per tile, the items
// whose screen box touches it, in the order they were added (scene order). Both the
// reference renderer and the accelerator's functional engine render tile by tile, in
// parallel over tiles and in scene order within a tile, so every pixel sees its
// primitives in scene order whatever the thread count.
#pragma once
#include <algorithm>
#include <cstddef>
#include <vector>

#include "raster/pixel/screen_box.h"

namespace qacc {

class TileBinner {
 public:
  static constexpr int kTileSize = 32;

  TileBinner(int width, int height)
      : width_(width), height_(height), tilesX_((width + kTileSize - 1) / kTileSize),
        tilesY_((height + kTileSize - 1) / kTileSize), bins_(std::size_t(tilesX_) * std::size_t(tilesY_)) {}

  // Adds item `index` to every tile its box touches (an empty box touches none).
  void add(int index, const ScreenBox& box) {
    const ScreenBox b = box.intersect({0, 0, width_, height_});
    if (b.empty()) return;
    for (int j = b.y0 / kTileSize; j <= (b.y1 - 1) / kTileSize; ++j)
      for (int i = b.x0 / kTileSize; i <= (b.x1 - 1) / kTileSize; ++i)
        bins_[std::size_t(j) * std::size_t(tilesX_) + std::size_t(i)].push_back(index);
  }

  int tiles() const { return tilesX_ * tilesY_; }
  // The items of tile t, in the order they were added.
  const std::vector<int>& bin(int t) const { return bins_[std::size_t(t)]; }
  // The pixels of tile t (clipped to the screen).
  ScreenBox tile(int t) const {
    const int x0 = (t % tilesX_) * kTileSize, y0 = (t / tilesX_) * kTileSize;
    return {x0, y0, std::min(width_, x0 + kTileSize), std::min(height_, y0 + kTileSize)};
  }

 private:
  int width_, height_, tilesX_, tilesY_;
  std::vector<std::vector<int>> bins_;
};

}  // namespace qacc
