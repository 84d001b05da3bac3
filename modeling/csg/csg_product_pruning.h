// A product of Goldfeather's normal form (csg_normal_form.h) pruned by its literals'
// boxes, in any space where every leaf lies inside its box (world, or normalised device
// coordinates of a view): the product is empty when its positive literals' boxes have no
// common point (an intersection of disjoint solids), and a complemented literal whose box
// misses the positive literals' common box is dropped (it removes nothing there). Boxes
// that only touch meet. The pruned product is the same point set as the product.
#pragma once
#include <vector>

#include <Eigen/Geometry>

#include "modeling/csg/csg_normal_form.h"

namespace qacc {

// `boxes` holds a box per scene primitive (indexed by CsgLiteral::primitive). Returns the
// pruned product, empty when the product is empty; a product without positive literals
// is returned as it is.
CsgProduct pruneProduct(const CsgProduct& product, const std::vector<Eigen::AlignedBox3d>& boxes);

}  // namespace qacc
