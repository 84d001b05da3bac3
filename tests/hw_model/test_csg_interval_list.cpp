// The bounded per-pixel interval list of the CSG path (hw_model/datapath/csg_interval_list.h)
// and its price in the cost model.
#include <gtest/gtest.h>

#include "hw_model/datapath/csg_interval_list.h"
#include "hw_model/report/cost_model.h"

using namespace qacc;

namespace {
CsgListInterval iv(std::int64_t zin, int leaf) { return {zin, zin + 10, leaf, -1, -1}; }
}  // namespace

TEST(CsgIntervalList, KeepsIntervalsInEntryOrderUpToItsDepth) {
  CsgIntervalList l;
  EXPECT_TRUE(l.insert(iv(30, 0), 3));
  EXPECT_TRUE(l.insert(iv(10, 1), 3));
  EXPECT_TRUE(l.insert(iv(30, 2), 3));  // equal entry: after the earlier arrival
  ASSERT_EQ(l.intervals().size(), 3u);
  EXPECT_EQ(l.intervals()[0].leaf, 1);
  EXPECT_EQ(l.intervals()[1].leaf, 0);
  EXPECT_EQ(l.intervals()[2].leaf, 2);
  EXPECT_FALSE(l.overflowed());
}

TEST(CsgIntervalList, OnOverflowKeepsTheNearestAndMarksThePixel) {
  CsgIntervalList l;
  for (int k = 0; k < 3; ++k) l.insert(iv(100 + 10 * k, k), 3);
  EXPECT_FALSE(l.insert(iv(200, 3), 3));  // farther than every kept one: dropped
  EXPECT_TRUE(l.overflowed());
  EXPECT_EQ(l.intervals().back().leaf, 2);
  EXPECT_FALSE(l.insert(iv(5, 4), 3));  // nearer: replaces the farthest
  ASSERT_EQ(l.intervals().size(), 3u);
  EXPECT_EQ(l.intervals()[0].leaf, 4);
  EXPECT_EQ(l.intervals()[2].leaf, 1);
  EXPECT_FALSE(l.insert(iv(105, 5), 3));  // between: the farthest (leaf 1, entry 110) goes
  EXPECT_EQ(l.intervals()[2].leaf, 5);
  l.clear();
  EXPECT_FALSE(l.overflowed());
  EXPECT_TRUE(l.intervals().empty());
}

TEST(CsgIntervalList, StorageFollowsDepthAndFormats) {
  HwConfig c;
  c.csg_list_depth = 32;
  c.depth_bits = 32;
  c.csg_leaf_bits = 11;
  c.csg_tag_bits = 4;
  // count (6 bits for 0..32) + overflow flag + 32 x (2 x 32 + 11 + 2 x 4)
  EXPECT_EQ(csgListCountBits(c), 6);
  EXPECT_EQ(csgListBitsPerPixel(c), 6 + 1 + 32 * 83);
  c.depth_bits = 24;
  EXPECT_EQ(csgListBitsPerPixel(c), 6 + 1 + 32 * 67);
}

TEST(CsgIntervalList, ThePriceGrowsWithTheListDepth) {
  HwConfig small, large;
  small.csg_list_depth = 8;
  large.csg_list_depth = 32;
  const CostModel a = CostModel::of(small), b = CostModel::of(large);
  EXPECT_GT(b.csgGe(), a.csgGe());
  EXPECT_GT(b.csgListBits, a.csgListBits);
  EXPECT_DOUBLE_EQ(b.csgListBits, double(kCsgListBuffers) * 32 * 32 * csgListBitsPerPixel(large));
  EXPECT_GT(a.csgGe(), 0);
  // The option is priced apart: the base machine's total does not move.
  EXPECT_DOUBLE_EQ(a.totalGe(), b.totalGe());
}
