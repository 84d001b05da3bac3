// Tile pruning of a product-at-a-time CSG method: products whose operands cannot meet in a
// tile are skipped there, complements that miss a tile are dropped from it.
#include <gtest/gtest.h>

#include "raster/pixel/csg_tile_work.h"

using namespace qacc;

TEST(CsgTileWork, SkipsProductsWhoseOperandsDoNotMeet) {
  // Two tiles side by side (64x32); A lies in the left tile, B in the right, C in both.
  const std::vector<ScreenBox> boxes{{2, 2, 20, 20}, {40, 2, 60, 20}, {0, 0, 64, 32}};
  CsgNormalForm f;
  f.products = {{{0, false}, {1, false}},   // A ∩ B: empty everywhere
                {{2, false}, {1, true}}};  // C − B: B matters only in the right tile
  const ScreenBox tree{0, 0, 64, 32};
  const CsgTileWork all = csgTileWork(f, boxes, tree, 64, 32, false);
  EXPECT_EQ(all.tiles, 2u);
  EXPECT_EQ(all.products, 4u);
  EXPECT_EQ(all.passes, 16u);
  const CsgTileWork pruned = csgTileWork(f, boxes, tree, 64, 32, true);
  EXPECT_EQ(pruned.tiles, 2u);
  EXPECT_EQ(pruned.products, 2u);        // C − B in both tiles, A ∩ B in none
  EXPECT_EQ(pruned.passes, 1u + 4u);     // left: C alone; right: C and ¬B
}
