#include "raster/pixel/csg_tile_work.h"

#include "raster/pixel/tile_binner.h"

namespace qacc {

CsgTileWork csgTileWork(const CsgNormalForm& form, const std::vector<ScreenBox>& boxes, const ScreenBox& treeBox,
                        int width, int height, bool prune) {
  CsgTileWork w;
  const TileBinner tiles(width, height);
  for (int t = 0; t < tiles.tiles(); ++t) {
    const ScreenBox tile = tiles.tile(t);
    if (treeBox.intersect(tile).empty()) continue;
    ++w.tiles;
    for (const CsgProduct& p : form.products) {
      std::uint64_t k = 0;
      ScreenBox positive = tile;
      for (const CsgLiteral& l : p) {
        const ScreenBox& b = boxes[std::size_t(l.primitive)];
        if (!prune) {
          ++k;
        } else if (l.complement) {
          k += !b.intersect(tile).empty();
        } else {
          positive = positive.intersect(b);
          ++k;
        }
      }
      if (prune && positive.empty()) continue;
      ++w.products;
      w.passes += k * k;
    }
  }
  return w;
}

}  // namespace qacc
