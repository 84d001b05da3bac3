// The exact visible point of a CSG tree (modeling/csg/csg_tree.h) on the line of one
// pixel: every solid leaf gives its depth intervals (pixel/solid_intervals.h, caps
// included), and a sweep along the line evaluates the Boolean tree at each boundary; the
// first boundary where the result turns from outside to inside (or, when the line starts
// inside at the near plane, the first real boundary beyond) is shown, with the winning
// leaf's normal flipped when the leaf is subtracted.
//
// Coincident faces: boundaries closer than kCsgDepthTolerance in window depth are one
// event (the same plane reached through a quadric root and through a clip plane differs by
// rounding), so a face shared by an operand and a subtracted solid neither shows nor
// leaves a hole in speckles. Of the boundaries of one event that turn the result, the
// earliest leaf in scene order wins (the depth rule of ties).
#pragma once
#include <vector>

#include "modeling/csg/csg_tree.h"
#include "raster/pixel/screen_box.h"
#include "raster/pixel/tile_binner.h"
#include "raster/pixel/window_primitive.h"

namespace qacc {

constexpr double kCsgDepthTolerance = 1e-9;

struct CsgHit {
  double z = 0;
  int primitive = -1;  // the leaf whose boundary is shown
  int cap = -1;        // its clip plane for a cap, -1 for its quadric surface
  int sign = 1;        // -1: the leaf is subtracted (its normal points into the result)
};

class CsgPixelTree {
 public:
  // `win` holds the window-space form of every scene primitive (indexed by primitive) for a
  // width x height image; the leaves are binned into the screen tiles of TileBinner.
  CsgPixelTree(const CsgTree& tree, const std::vector<WindowPrimitive>& win, int width, int height);
  // Pixels that can show the result (leaf boxes combined by the tree: union, intersection,
  // first operand of a difference).
  const ScreenBox& box() const { return box_; }
  bool hit(double x, double y, CsgHit& hit) const;

  // For engines that compute the leaves' intervals themselves (the accelerator): one end
  // of a leaf's interval, the leaves binned per tile, and the sweep over given ends
  // (`tolerance`: ends closer than this in window depth are one event).
  struct Boundary {
    double z;
    int leaf;  // index of the leaf (leafPrimitive)
    bool entering;
    int tag;   // DepthBound tag: surface, view or cap plane
  };
  int leafPrimitive(int leaf) const { return tree_->nodes[std::size_t(leafNode(leaf))].primitive; }
  int leafNode(int leaf) const { return leafNodes_[std::size_t(leaf)]; }  // its node in tree()
  int leafCount() const { return int(leafNodes_.size()); }
  const CsgTree& tree() const { return *tree_; }
  const std::vector<int>& leavesInTile(int tile) const { return leafBins_.bin(tile); }
  // The sweep keeps a counter per node of tree() and a leaf without ends leaves its counter
  // at zero, so the ends of the leaves of a pruned tree (modeling/csg/csg_tree_pruning.h,
  // which keeps the node numbering and drops only operands without points) are swept on
  // that pruned tree: a dropped operand, never entered, adds nothing to its parent.
  bool resolve(std::vector<Boundary>& ends, double tolerance, CsgHit& hit) const;

 private:
  const CsgTree* tree_;
  const std::vector<WindowPrimitive>* win_;
  std::vector<int> polarity_;   // per node
  std::vector<int> leafNodes_;  // node index of every leaf, in scene order
  std::vector<int> parent_;     // per node, -1 for the root
  std::vector<char> first_;     // per node: the first child of a difference
  ScreenBox box_;
  TileBinner leafBins_;         // leaves (indices into leafNodes_) per screen tile
  int tilesX_;

  ScreenBox nodeBox(int node) const;
  // Incremental evaluation: per node the number of children inside (for a difference, of
  // the subtracted ones) and whether a difference's first child is inside; a leaf's toggle
  // walks up while node values change. Every sweep ends with all leaves outside, so the
  // counters are back at zero for the next pixel.
  struct Counters {
    std::vector<int> inside;
    std::vector<char> firstIn;
  };
  bool value(int node, const Counters& c) const;
  void toggle(int leafNode, bool in, Counters& c) const;
};

}  // namespace qacc
