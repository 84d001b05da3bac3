#include "modeling/csg/csg_tree_pruning.h"

#include <stdexcept>
#include <string>

namespace qacc {
namespace {

struct Pruner {
  const CsgTree& in;
  const std::vector<char>& present;
  PrunedCsgTree& out;

  // Prunes node n (its children first) and returns whether it is non-empty; counts the
  // present leaves under it in `presentLeaves`.
  bool prune(int n, int& presentLeaves) {
    const CsgNode& node = in.nodes[std::size_t(n)];
    CsgNode& kept = out.tree.nodes[std::size_t(n)];
    kept.children.clear();
    bool nonEmpty = false;
    int below = 0;
    switch (node.op) {
      case CsgNode::Op::Leaf:
        nonEmpty = present[std::size_t(n)] != 0;
        below = nonEmpty ? 1 : 0;
        break;
      case CsgNode::Op::Union:
        for (int c : node.children)
          if (prune(c, below)) kept.children.push_back(c);
        nonEmpty = !kept.children.empty();
        break;
      case CsgNode::Op::Intersection:
        nonEmpty = true;
        for (int c : node.children) {
          nonEmpty &= prune(c, below);
          kept.children.push_back(c);
        }
        break;
      case CsgNode::Op::Difference:
        for (std::size_t i = 0; i < node.children.size(); ++i) {
          const int c = node.children[i];
          const bool childNonEmpty = prune(c, below);
          if (i == 0) nonEmpty = childNonEmpty;
          if (i == 0 || childNonEmpty) kept.children.push_back(c);
        }
        break;
    }
    if (!nonEmpty && node.op != CsgNode::Op::Leaf && below > 0) {
      ++out.productsPruned;
      out.leavesPruned += below;
      below = 0;  // counted here, not again by an empty ancestor
    }
    presentLeaves += below;
    return nonEmpty;
  }

  // Marks n and the nodes under it that the pruned tree reaches.
  void mark(int n) {
    out.kept[std::size_t(n)] = 1;
    for (int c : out.tree.nodes[std::size_t(n)].children) mark(c);
  }
};

}  // namespace

PrunedCsgTree pruneCsgTree(const CsgTree& tree, const std::vector<char>& present) {
  if (present.size() != tree.nodes.size())
    throw std::invalid_argument("pruneCsgTree: " + std::to_string(present.size()) + " presence flags for a tree of " +
                                std::to_string(tree.nodes.size()) + " nodes");
  PrunedCsgTree out;
  out.tree = tree;
  out.kept.assign(tree.nodes.size(), 0);
  if (tree.root < 0) return out;
  Pruner p{tree, present, out};
  int presentLeaves = 0;
  if (p.prune(tree.root, presentLeaves)) p.mark(tree.root);
  else out.tree.root = -1;
  return out;
}

}  // namespace qacc
