// Goldfeather's normal form of a CSG tree: the products are right by hand on small trees
// and agree with the tree on every assignment of inside/outside to the leaves.
#include <gtest/gtest.h>

#include <functional>
#include <random>

#include "modeling/csg/csg_normal_form.h"

using namespace qacc;

namespace {

using Op = CsgNode::Op;

struct TreeMaker {
  CsgTree t;
  int leaf(int primitive) {
    CsgNode n;
    n.primitive = primitive;
    t.nodes.push_back(n);
    return int(t.nodes.size()) - 1;
  }
  int node(Op op, std::vector<int> children) {
    CsgNode n;
    n.op = op;
    n.children = std::move(children);
    t.nodes.push_back(n);
    return int(t.nodes.size()) - 1;
  }
  CsgTree done(int root) {
    t.root = root;
    return t;
  }
};

bool treeInside(const CsgTree& t, int n, unsigned state) {
  const CsgNode& node = t.nodes[std::size_t(n)];
  switch (node.op) {
    case Op::Leaf: return (state >> node.primitive) & 1u;
    case Op::Union:
      for (int c : node.children)
        if (treeInside(t, c, state)) return true;
      return false;
    case Op::Intersection:
      for (int c : node.children)
        if (!treeInside(t, c, state)) return false;
      return true;
    case Op::Difference:
      if (!treeInside(t, node.children[0], state)) return false;
      for (std::size_t i = 1; i < node.children.size(); ++i)
        if (treeInside(t, node.children[i], state)) return false;
      return true;
  }
  return false;
}

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
    TreeMaker m;
    const CsgTree t = m.done(m.node(Op::Difference, {m.leaf(0), m.node(Op::Union, {m.leaf(1), m.leaf(2)})}));
    const CsgNormalForm f = normalForm(t);
    ASSERT_EQ(f.products.size(), 1u);
    EXPECT_EQ(f.products[0], (CsgProduct{{0, false}, {1, true}, {2, true}}));
    EXPECT_EQ(f.passes(), 9u);
  }
  {  // A − (B − C) = A ¬B ∪ A C
    TreeMaker m;
    const CsgTree t = m.done(m.node(Op::Difference, {m.leaf(0), m.node(Op::Difference, {m.leaf(1), m.leaf(2)})}));
    const CsgNormalForm f = normalForm(t);
    ASSERT_EQ(f.products.size(), 2u);
    EXPECT_EQ(f.products[0], (CsgProduct{{0, false}, {1, true}}));
    EXPECT_EQ(f.products[1], (CsgProduct{{0, false}, {2, false}}));
  }
  {  // A ∩ (B − A): the product holds A and ¬A and is dropped
    TreeMaker m;
    const int a1 = m.leaf(0), a2 = m.leaf(0);
    const CsgTree t = m.done(m.node(Op::Intersection, {a1, m.node(Op::Difference, {m.leaf(1), a2})}));
    EXPECT_TRUE(normalForm(t).products.empty());
  }
}

TEST(CsgNormalForm, AgreesWithTheTreeOnEveryLeafState) {
  std::mt19937 rng(7);
  for (int trial = 0; trial < 200; ++trial) {
    TreeMaker m;
    std::function<int(int)> grow = [&](int depth) -> int {
      if (depth == 0 || rng() % 4 == 0) return m.leaf(int(rng() % 6));
      const Op op = Op(1 + rng() % 3);
      std::vector<int> c;
      const int n = 1 + int(rng() % 3);
      for (int i = 0; i < n; ++i) c.push_back(grow(depth - 1));
      return m.node(op, c);
    };
    const CsgTree t = m.done(grow(4));
    const CsgNormalForm f = normalForm(t);
    ASSERT_TRUE(f.complete);
    for (unsigned state = 0; state < 64; ++state)
      ASSERT_EQ(formInside(f, state), treeInside(t, t.root, state)) << "trial " << trial << " state " << state;
  }
}
