// CsgTree: the Boolean tree of one `csg` scene object (docs/SCENES.md). Leaves are solid
// primitives of Scene::primitives (the interior f <= 0 inside the clip polyhedron);
// inner nodes combine their children by union, intersection or difference (the first
// child minus every later one). A leaf's polarity says whether its solid counts as
// material (+1) or as a hole (-1): it flips under every subtracted position, and decides
// which way its surface normal faces in the result.
#pragma once
#include <vector>

namespace qacc {

struct CsgNode {
  enum class Op { Leaf, Union, Intersection, Difference };
  Op op = Op::Leaf;
  std::vector<int> children;  // indices into CsgTree::nodes, in scene order
  int primitive = -1;         // leaves: index into Scene::primitives
};

struct CsgTree {
  int object = -1;             // index into Scene::objects of the `csg` object
  std::vector<CsgNode> nodes;  // nodes[root] is the whole tree
  int root = -1;

  // The leaves' primitives in scene order.
  std::vector<int> leafPrimitives() const;
  // +1 or -1 per node (material or hole in the result), in node order.
  std::vector<int> polarities() const;
  // Number of nodes from the root to the deepest leaf (a lone leaf has depth 1).
  int depth() const;
};

const char* csgOpName(CsgNode::Op op);

}  // namespace qacc
