// A product of the normal form pruned by its literals' boxes (modeling/csg/
// csg_product_pruning.h): disjoint positive boxes empty it, a complemented literal whose
// box misses the positive ones is left out, boxes that only touch are kept.
#include <gtest/gtest.h>

#include "modeling/csg/csg_product_pruning.h"

using namespace qacc;

namespace {

Eigen::AlignedBox3d box(double x0, double x1) {
  return Eigen::AlignedBox3d(Eigen::Vector3d(x0, 0, 0), Eigen::Vector3d(x1, 1, 1));
}

}  // namespace

TEST(CsgProductPruning, DisjointPositiveLeavesEmptyTheProduct) {
  const std::vector<Eigen::AlignedBox3d> boxes{box(0, 1), box(2, 3), box(0.5, 2.5)};
  EXPECT_TRUE(pruneProduct({{0, false}, {1, false}}, boxes).empty());
  // Pairwise the third meets both, but the three have no common point.
  EXPECT_TRUE(pruneProduct({{0, false}, {1, false}, {2, false}}, boxes).empty());
  EXPECT_EQ(pruneProduct({{0, false}, {2, false}}, boxes).size(), 2u);
}

TEST(CsgProductPruning, AComplementApartIsLeftOut) {
  const std::vector<Eigen::AlignedBox3d> boxes{box(0, 1), box(2, 3), box(0.5, 2.5)};
  const CsgProduct kept = pruneProduct({{0, false}, {1, true}, {2, true}}, boxes);
  ASSERT_EQ(kept.size(), 2u);
  EXPECT_EQ(kept[0], (CsgLiteral{0, false}));
  EXPECT_EQ(kept[1], (CsgLiteral{2, true}));
  // Against the common box of the positives, not each positive alone: 1 meets 2 but not 0 ∩ 2.
  const CsgProduct common = pruneProduct({{0, false}, {2, false}, {1, true}}, boxes);
  EXPECT_EQ(common, (CsgProduct{{0, false}, {2, false}}));
}

TEST(CsgProductPruning, TouchingBoxesAreKept) {
  const std::vector<Eigen::AlignedBox3d> boxes{box(0, 1), box(1, 2)};
  EXPECT_EQ(pruneProduct({{0, false}, {1, false}}, boxes).size(), 2u);
  EXPECT_EQ(pruneProduct({{0, false}, {1, true}}, boxes).size(), 2u);
}

TEST(CsgProductPruning, EmptyLeavesAndProductsWithoutPositives) {
  const std::vector<Eigen::AlignedBox3d> boxes{box(0, 1), Eigen::AlignedBox3d()};  // leaf 1 drew nothing
  EXPECT_TRUE(pruneProduct({{0, false}, {1, false}}, boxes).empty());
  EXPECT_EQ(pruneProduct({{0, false}, {1, true}}, boxes), (CsgProduct{{0, false}}));
  EXPECT_EQ(pruneProduct({{0, true}, {1, true}}, boxes).size(), 2u);
}
