// A CsgTree (csg_tree.h) pruned for one region of space, a screen tile of the accelerator,
// given which leaves are present there (their boxes touch it; an absent leaf has no point
// in the region): an absent leaf is empty; an intersection with an empty operand is empty;
// a difference whose first operand is empty is empty, and its empty subtracted operands
// are dropped; a union drops its empty children. Inside the region the pruned tree is the
// same point set as the tree. Its leaves are the ones still needed there: a present leaf
// under an empty intersection (or under a difference whose first operand is empty) is not.
//
// The pruned tree keeps the node numbering of the tree (a dropped node stays in `nodes`
// but no kept node points at it, its `kept` flag is 0), so per-node data of the tree
// (polarities, parents, a difference's first child) holds for it unchanged; no node is
// collapsed into its parent.
#pragma once
#include <vector>

#include "modeling/csg/csg_tree.h"

namespace qacc {

struct PrunedCsgTree {
  CsgTree tree;             // root -1 when the whole tree is empty in the region
  std::vector<char> kept;   // per node of the tree: 1 when it is in the pruned tree
  int leavesPruned = 0;     // present leaves that are not needed (under an empty node)
  int productsPruned = 0;   // intersections and differences found empty with a present leaf under them
};

// `present` holds a flag per node of `tree` (only leaves' flags are read): 1 when the
// leaf has points in the region. Throws std::invalid_argument when its size differs from
// the tree's node count.
PrunedCsgTree pruneCsgTree(const CsgTree& tree, const std::vector<char>& present);

}  // namespace qacc
