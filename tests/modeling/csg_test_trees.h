// CSG trees for the modeling tests: a builder of small trees node by node, random trees,
// and the value of a tree at a state of its leaves (bit p of `state`: inside primitive p).
#pragma once
#include <functional>
#include <random>
#include <utility>
#include <vector>

#include "modeling/csg/csg_tree.h"

struct CsgTreeMaker {
  qacc::CsgTree t;
  int leaf(int primitive) {
    qacc::CsgNode n;
    n.primitive = primitive;
    t.nodes.push_back(n);
    return int(t.nodes.size()) - 1;
  }
  int node(qacc::CsgNode::Op op, std::vector<int> children) {
    qacc::CsgNode n;
    n.op = op;
    n.children = std::move(children);
    t.nodes.push_back(n);
    return int(t.nodes.size()) - 1;
  }
  qacc::CsgTree done(int root) {
    t.root = root;
    return t;
  }
};

// A random tree of at most `depth` levels over primitives 0..5 (a node is a leaf at the
// last level or with probability 1/4; an inner node has 1 to 3 children).
inline qacc::CsgTree randomCsgTree(std::mt19937& rng, int depth) {
  using Op = qacc::CsgNode::Op;
  CsgTreeMaker m;
  std::function<int(int)> grow = [&](int d) -> int {
    if (d == 0 || rng() % 4 == 0) return m.leaf(int(rng() % 6));
    const Op op = Op(1 + rng() % 3);
    std::vector<int> c;
    const int n = 1 + int(rng() % 3);
    for (int i = 0; i < n; ++i) c.push_back(grow(d - 1));
    return m.node(op, c);
  };
  return m.done(grow(depth));
}

inline bool csgTreeInside(const qacc::CsgTree& t, int n, unsigned state) {
  using Op = qacc::CsgNode::Op;
  const qacc::CsgNode& node = t.nodes[std::size_t(n)];
  switch (node.op) {
    case Op::Leaf: return (state >> node.primitive) & 1u;
    case Op::Union:
      for (int c : node.children)
        if (csgTreeInside(t, c, state)) return true;
      return false;
    case Op::Intersection:
      for (int c : node.children)
        if (!csgTreeInside(t, c, state)) return false;
      return true;
    case Op::Difference:
      if (!csgTreeInside(t, node.children[0], state)) return false;
      for (std::size_t i = 1; i < node.children.size(); ++i)
        if (csgTreeInside(t, node.children[i], state)) return false;
      return true;
  }
  return false;
}
