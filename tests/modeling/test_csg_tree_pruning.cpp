// A CSG tree pruned for a region by its leaves' presence: the rules by hand on small trees
// (intersections, differences' first and subtracted operands, unions), the leaves still
// needed, the counts, and on random trees the same value as the tree at every state of the
// leaves in which the absent ones are outside.
#include <gtest/gtest.h>

#include <random>
#include <stdexcept>

#include "modeling/csg/csg_tree_pruning.h"
#include "tests/modeling/csg_test_trees.h"

using namespace qacc;

namespace {

using Op = CsgNode::Op;

// Per node of t: 1 for a leaf whose primitive is in `primitives`.
std::vector<char> presentLeaves(const CsgTree& t, std::vector<int> primitives) {
  std::vector<char> p(t.nodes.size(), 0);
  for (std::size_t n = 0; n < t.nodes.size(); ++n)
    for (int q : primitives) p[n] |= t.nodes[n].op == Op::Leaf && t.nodes[n].primitive == q;
  return p;
}

}  // namespace

TEST(CsgTreePruning, IntersectionWithAnAbsentOperandIsEmpty) {
  // (A ∩ B) ∪ C with B absent: the intersection goes, and A with it.
  CsgTreeMaker m;
  const int a = m.leaf(0), b = m.leaf(1), c = m.leaf(2);
  const int i = m.node(Op::Intersection, {a, b});
  const CsgTree t = m.done(m.node(Op::Union, {i, c}));
  const PrunedCsgTree p = pruneCsgTree(t, presentLeaves(t, {0, 2}));
  EXPECT_EQ(p.tree.root, t.root);
  EXPECT_EQ(p.tree.leafPrimitives(), std::vector<int>({2}));
  EXPECT_EQ(p.tree.nodes[std::size_t(t.root)].children, std::vector<int>({c}));
  EXPECT_FALSE(p.kept[std::size_t(i)]);
  EXPECT_FALSE(p.kept[std::size_t(a)]);
  EXPECT_EQ(p.leavesPruned, 1);
  EXPECT_EQ(p.productsPruned, 1);
  // With every leaf present nothing changes.
  const PrunedCsgTree all = pruneCsgTree(t, presentLeaves(t, {0, 1, 2}));
  EXPECT_EQ(all.tree.leafPrimitives(), t.leafPrimitives());
  EXPECT_EQ(all.leavesPruned, 0);
  EXPECT_EQ(all.productsPruned, 0);
}

TEST(CsgTreePruning, DifferenceKeepsItsPresentSubtractedOperandsOnly) {
  // A − B − (C ∩ D) − E with B and D absent: A − E remains; B is dropped; C ∩ D is empty
  // (C pruned); E, present, must stay subtracted.
  CsgTreeMaker m;
  const int a = m.leaf(0), b = m.leaf(1), c = m.leaf(2), d = m.leaf(3), e = m.leaf(4);
  const int cd = m.node(Op::Intersection, {c, d});
  const CsgTree t = m.done(m.node(Op::Difference, {a, b, cd, e}));
  const PrunedCsgTree p = pruneCsgTree(t, presentLeaves(t, {0, 2, 4}));
  ASSERT_EQ(p.tree.root, t.root);
  EXPECT_EQ(p.tree.nodes[std::size_t(t.root)].children, std::vector<int>({a, e}));
  EXPECT_EQ(p.tree.leafPrimitives(), std::vector<int>({0, 4}));
  EXPECT_EQ(p.leavesPruned, 1);
  EXPECT_EQ(p.productsPruned, 1);
}

TEST(CsgTreePruning, DifferenceWithAnAbsentFirstOperandIsEmpty) {
  // (A − B) ∪ C with A absent: B is present but not needed.
  CsgTreeMaker m;
  const int a = m.leaf(0), b = m.leaf(1), c = m.leaf(2);
  const int d = m.node(Op::Difference, {a, b});
  const CsgTree t = m.done(m.node(Op::Union, {d, c}));
  const PrunedCsgTree p = pruneCsgTree(t, presentLeaves(t, {1, 2}));
  EXPECT_EQ(p.tree.leafPrimitives(), std::vector<int>({2}));
  EXPECT_EQ(p.leavesPruned, 1);
  EXPECT_EQ(p.productsPruned, 1);
  // Alone, the difference empties the whole tree.
  CsgTreeMaker m2;
  const int a2 = m2.leaf(0), b2 = m2.leaf(1);
  const CsgTree t2 = m2.done(m2.node(Op::Difference, {a2, b2}));
  const PrunedCsgTree p2 = pruneCsgTree(t2, presentLeaves(t2, {1}));
  EXPECT_EQ(p2.tree.root, -1);
  EXPECT_TRUE(p2.tree.leafPrimitives().empty());
  EXPECT_EQ(p2.leavesPruned, 1);
}

TEST(CsgTreePruning, UnionDropsItsEmptyChildren) {
  CsgTreeMaker m;
  const int a = m.leaf(0), b = m.leaf(1), c = m.leaf(2);
  const CsgTree t = m.done(m.node(Op::Union, {a, b, c}));
  const PrunedCsgTree p = pruneCsgTree(t, presentLeaves(t, {0, 2}));
  EXPECT_EQ(p.tree.nodes[std::size_t(t.root)].children, std::vector<int>({a, c}));
  EXPECT_EQ(p.leavesPruned, 0);  // an absent leaf is not counted as pruned
  EXPECT_EQ(p.productsPruned, 0);
  const PrunedCsgTree none = pruneCsgTree(t, presentLeaves(t, {}));
  EXPECT_EQ(none.tree.root, -1);
  EXPECT_EQ(none.leavesPruned, 0);
}

TEST(CsgTreePruning, RefusesPresenceOfTheWrongSize) {
  CsgTreeMaker m;
  const CsgTree t = m.done(m.leaf(0));
  EXPECT_THROW(pruneCsgTree(t, std::vector<char>(2, 1)), std::invalid_argument);
}

TEST(CsgTreePruning, AgreesWithTheTreeWhereTheAbsentLeavesAreOutside) {
  std::mt19937 rng(11);
  for (int trial = 0; trial < 300; ++trial) {
    const CsgTree t = randomCsgTree(rng, 4);
    const unsigned presentMask = unsigned(rng() % 64);
    std::vector<int> present;
    for (int q = 0; q < 6; ++q)
      if ((presentMask >> q) & 1u) present.push_back(q);
    const PrunedCsgTree p = pruneCsgTree(t, presentLeaves(t, present));
    for (int q : p.tree.leafPrimitives()) ASSERT_TRUE((presentMask >> q) & 1u) << "trial " << trial;
    for (unsigned state = 0; state < 64; ++state) {
      if (state & ~presentMask) continue;  // an absent leaf has no point in the region
      const bool pruned = p.tree.root >= 0 && csgTreeInside(p.tree, p.tree.root, state);
      ASSERT_EQ(pruned, csgTreeInside(t, t.root, state)) << "trial " << trial << " state " << state;
    }
  }
}
