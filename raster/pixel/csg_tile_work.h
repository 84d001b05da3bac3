// The work a product-at-a-time CSG method (Goldfeather's normal form, modeling/csg/
// csg_normal_form.h) does per screen tile, with and without pruning by the operands'
// screen boxes. Without pruning every product is drawn, with all its literals, in every
// tile the tree's box touches. With pruning a product is skipped in a tile its positive
// literals' boxes do not all touch (their intersection is empty there), and a
// complemented literal whose box misses the tile is dropped from the product there (its
// complement is the whole tile); passes are k² for the k literals left (csg_normal_form.h).
#pragma once
#include <cstdint>
#include <vector>

#include "modeling/csg/csg_normal_form.h"
#include "raster/pixel/screen_box.h"

namespace qacc {

struct CsgTileWork {
  std::uint64_t tiles = 0;     // tiles the tree's box touches
  std::uint64_t products = 0;  // (tile, product) pairs drawn
  std::uint64_t passes = 0;    // passes over those tiles
};

// `boxes` holds the screen box of every scene primitive (indexed by primitive).
CsgTileWork csgTileWork(const CsgNormalForm& form, const std::vector<ScreenBox>& boxes, const ScreenBox& treeBox,
                        int width, int height, bool prune);

}  // namespace qacc
