#include "modeling/csg/csg_tree.h"

#include <algorithm>

namespace qacc {
namespace {

void collectLeaves(const CsgTree& t, int n, std::vector<int>& out) {
  const CsgNode& node = t.nodes[std::size_t(n)];
  if (node.op == CsgNode::Op::Leaf) {
    out.push_back(node.primitive);
    return;
  }
  for (int c : node.children) collectLeaves(t, c, out);
}

void assignPolarity(const CsgTree& t, int n, int polarity, std::vector<int>& out) {
  out[std::size_t(n)] = polarity;
  const CsgNode& node = t.nodes[std::size_t(n)];
  for (std::size_t i = 0; i < node.children.size(); ++i) {
    const bool subtracted = node.op == CsgNode::Op::Difference && i > 0;
    assignPolarity(t, node.children[i], subtracted ? -polarity : polarity, out);
  }
}

int depthOf(const CsgTree& t, int n) {
  int d = 0;
  for (int c : t.nodes[std::size_t(n)].children) d = std::max(d, depthOf(t, c));
  return d + 1;
}

}  // namespace

std::vector<int> CsgTree::leafPrimitives() const {
  std::vector<int> out;
  if (root >= 0) collectLeaves(*this, root, out);
  return out;
}

std::vector<int> CsgTree::polarities() const {
  std::vector<int> out(nodes.size(), 1);
  if (root >= 0) assignPolarity(*this, root, 1, out);
  return out;
}

int CsgTree::depth() const { return root >= 0 ? depthOf(*this, root) : 0; }

const char* csgOpName(CsgNode::Op op) {
  switch (op) {
    case CsgNode::Op::Union: return "union";
    case CsgNode::Op::Intersection: return "intersection";
    case CsgNode::Op::Difference: return "difference";
    case CsgNode::Op::Leaf: break;
  }
  return "leaf";
}

}  // namespace qacc
