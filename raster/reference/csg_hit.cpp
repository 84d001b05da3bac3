#include "raster/reference/csg_hit.h"

#include <algorithm>

#include "raster/pixel/solid_intervals.h"

namespace qacc {
namespace {

bool contains(const ScreenBox& b, int x, int y) { return x >= b.x0 && x < b.x1 && y >= b.y0 && y < b.y1; }

}  // namespace

CsgPixelTree::CsgPixelTree(const CsgTree& tree, const std::vector<WindowPrimitive>& win, int width, int height)
    : tree_(&tree), win_(&win), polarity_(tree.polarities()), parent_(tree.nodes.size(), -1),
      first_(tree.nodes.size(), 0), leafBins_(width, height),
      tilesX_((width + TileBinner::kTileSize - 1) / TileBinner::kTileSize) {
  for (std::size_t n = 0; n < tree.nodes.size(); ++n) {
    const CsgNode& node = tree.nodes[n];
    if (node.op == CsgNode::Op::Leaf) leafNodes_.push_back(int(n));
    for (std::size_t i = 0; i < node.children.size(); ++i) {
      parent_[std::size_t(node.children[i])] = int(n);
      first_[std::size_t(node.children[i])] = node.op == CsgNode::Op::Difference && i == 0;
    }
  }
  std::sort(leafNodes_.begin(), leafNodes_.end(),
            [&](int a, int b) { return tree.nodes[std::size_t(a)].primitive < tree.nodes[std::size_t(b)].primitive; });
  for (int l = 0; l < int(leafNodes_.size()); ++l)
    leafBins_.add(l, win[std::size_t(tree.nodes[std::size_t(leafNodes_[std::size_t(l)])].primitive)].box);
  box_ = tree.root >= 0 ? nodeBox(tree.root) : ScreenBox{};
}

ScreenBox CsgPixelTree::nodeBox(int node) const {
  const CsgNode& n = tree_->nodes[std::size_t(node)];
  switch (n.op) {
    case CsgNode::Op::Leaf: return (*win_)[std::size_t(n.primitive)].box;
    case CsgNode::Op::Difference: return nodeBox(n.children[0]);
    case CsgNode::Op::Intersection: {
      ScreenBox b = nodeBox(n.children[0]);
      for (std::size_t i = 1; i < n.children.size(); ++i) b = b.intersect(nodeBox(n.children[i]));
      return b;
    }
    case CsgNode::Op::Union: break;
  }
  ScreenBox b;
  for (int c : n.children) {
    const ScreenBox cb = nodeBox(c);
    if (cb.empty()) continue;
    b = b.empty() ? cb : ScreenBox{std::min(b.x0, cb.x0), std::min(b.y0, cb.y0), std::max(b.x1, cb.x1), std::max(b.y1, cb.y1)};
  }
  return b;
}

bool CsgPixelTree::value(int node, const Counters& c) const {
  const CsgNode& n = tree_->nodes[std::size_t(node)];
  const int k = c.inside[std::size_t(node)];
  switch (n.op) {
    case CsgNode::Op::Leaf:
    case CsgNode::Op::Union: return k > 0;
    case CsgNode::Op::Intersection: return k == int(n.children.size());
    case CsgNode::Op::Difference: return c.firstIn[std::size_t(node)] && k == 0;
  }
  return false;
}

void CsgPixelTree::toggle(int leafNode, bool in, Counters& c) const {
  int n = leafNode;
  bool before = value(n, c);
  c.inside[std::size_t(n)] = in ? 1 : 0;
  bool after = value(n, c);
  while (before != after && parent_[std::size_t(n)] >= 0) {
    const int p = parent_[std::size_t(n)];
    before = value(p, c);
    if (first_[std::size_t(n)]) c.firstIn[std::size_t(p)] = after;
    else c.inside[std::size_t(p)] += after ? 1 : -1;
    after = value(p, c);
    n = p;
  }
}

bool CsgPixelTree::hit(double x, double y, CsgHit& hit) const {
  thread_local std::vector<Boundary> events;
  events.clear();
  const int px = int(x), py = int(y);
  if (px < 0 || py < 0) return false;
  const int tile = (py / TileBinner::kTileSize) * tilesX_ + px / TileBinner::kTileSize;
  if (tile >= leafBins_.tiles()) return false;
  for (int l : leafBins_.bin(tile)) {
    const WindowPrimitive& w = (*win_)[std::size_t(leafPrimitive(l))];
    if (!contains(w.box, px, py)) continue;
    DepthInterval iv[2];
    const int n = solidIntervals(w, x, y, iv);
    for (int k = 0; k < n; ++k) {
      events.push_back({iv[k].in.z, l, true, iv[k].in.tag});
      events.push_back({iv[k].out.z, l, false, iv[k].out.tag});
    }
  }
  return resolve(events, kCsgDepthTolerance, hit);
}

bool CsgPixelTree::resolve(std::vector<Boundary>& events, double tolerance, CsgHit& hit) const {
  thread_local Counters counters;
  thread_local const CsgPixelTree* countersOf = nullptr;
  if (countersOf != this || counters.inside.size() != tree_->nodes.size()) {
    counters.inside.assign(tree_->nodes.size(), 0);
    counters.firstIn.assign(tree_->nodes.size(), 0);
    countersOf = this;
  }
  if (events.empty()) return false;
  // By depth; at equal depth exits first (two touching intervals of one leaf stay inside).
  std::sort(events.begin(), events.end(), [](const Boundary& a, const Boundary& b) {
    if (a.z != b.z) return a.z < b.z;
    if (a.entering != b.entering) return !a.entering;
    return a.leaf < b.leaf;
  });
  bool before = false, found = false;
  std::size_t i = 0;
  while (i < events.size()) {
    std::size_t j = i;
    for (; j < events.size() && events[j].z - events[i].z <= tolerance; ++j)
      toggle(leafNodes_[std::size_t(events[j].leaf)], events[j].entering, counters);
    const bool now = value(tree_->root, counters);
    if (now != before) {
      int best = -1;
      for (std::size_t k = i; k < j; ++k) {
        const Boundary& e = events[k];
        if (e.tag == DepthBound::kView) continue;
        const bool material = polarity_[std::size_t(leafNodes_[std::size_t(e.leaf)])] > 0;
        // The boundaries that turn the result the same way: material entered or hole left
        // when the result is entered, and the reverse when it is left.
        const bool turns = now ? e.entering == material : e.entering != material;
        if (turns && (best < 0 || e.leaf < events[std::size_t(best)].leaf)) best = int(k);
      }
      if (best >= 0) {
        const Boundary& e = events[std::size_t(best)];
        const int node = leafNodes_[std::size_t(e.leaf)];
        hit.z = e.z;
        hit.primitive = tree_->nodes[std::size_t(node)].primitive;
        hit.cap = e.tag >= 0 ? e.tag : -1;
        hit.sign = polarity_[std::size_t(node)];
        found = true;
        i = j;
        break;
      }
      before = now;
    }
    i = j;
  }
  // Leave every leaf outside again (the counters return to zero).
  for (; i < events.size(); ++i) toggle(leafNodes_[std::size_t(events[i].leaf)], events[i].entering, counters);
  return found;
}

}  // namespace qacc
