// Goldfeather's normal form of a CSG tree: the products are right by hand on small trees
// and agree with the tree on every assignment of inside/outside to the leaves.
#include <gtest/gtest.h>

#include <random>

#include "modeling/csg/csg_normal_form.h"
#include "tests/modeling/csg_test_trees.h"

using namespace qacc;

namespace {

using Op = CsgNode::Op;

bool formInside(const CsgNormalForm& f, unsigned state) {
  for (const CsgProduct& p : f.products) {
    bool all = true;
    for (const CsgLiteral& l : p) all = all && (((state >> l.primitive) & 1u) != 0) != l.complement;
    if (all) return true;
  }
  return false;
}

}  // namespace

TEST(CsgNormalForm, SmallTreesByHand) {
  {  // A − (B ∪ C) = A ¬B ¬C
    CsgTreeMaker m;
    const CsgTree t = m.done(m.node(Op::Difference, {m.leaf(0), m.node(Op::Union, {m.leaf(1), m.leaf(2)})}));
    const CsgNormalForm f = normalForm(t);
    ASSERT_EQ(f.products.size(), 1u);
    EXPECT_EQ(f.products[0], (CsgProduct{{0, false}, {1, true}, {2, true}}));
    EXPECT_EQ(f.passes(), 9u);
  }
  {  // A − (B − C) = A ¬B ∪ A C
    CsgTreeMaker m;
    const CsgTree t = m.done(m.node(Op::Difference, {m.leaf(0), m.node(Op::Difference, {m.leaf(1), m.leaf(2)})}));
    const CsgNormalForm f = normalForm(t);
    ASSERT_EQ(f.products.size(), 2u);
    EXPECT_EQ(f.products[0], (CsgProduct{{0, false}, {1, true}}));
    EXPECT_EQ(f.products[1], (CsgProduct{{0, false}, {2, false}}));
  }
  {  // A ∩ (B − A): the product holds A and ¬A and is dropped
    CsgTreeMaker m;
    const int a1 = m.leaf(0), a2 = m.leaf(0);
    const CsgTree t = m.done(m.node(Op::Intersection, {a1, m.node(Op::Difference, {m.leaf(1), a2})}));
    EXPECT_TRUE(normalForm(t).products.empty());
  }
}

TEST(CsgNormalForm, AgreesWithTheTreeOnEveryLeafState) {
  std::mt19937 rng(7);
  for (int trial = 0; trial < 200; ++trial) {
    const CsgTree t = randomCsgTree(rng, 4);
    const CsgNormalForm f = normalForm(t);
    ASSERT_TRUE(f.complete);
    for (unsigned state = 0; state < 64; ++state)
      ASSERT_EQ(formInside(f, state), csgTreeInside(t, t.root, state)) << "trial " << trial << " state " << state;
  }
}
