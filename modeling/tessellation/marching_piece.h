// Quadric pieces without a parametric grid (hyperbolic paraboloid, parabolic and hyperbolic
// cylinders, the degenerate types, and small clipped pieces a grid misses): marching
// tetrahedra (modeling/algebraic/marching_tetrahedra.h) over the part of the region's box
// where the surface can be, edge points refined onto the surface by Newton steps along the
// gradient, the triangles clipped by the piece's planes through the surface builder.
#pragma once
#include <vector>

#include <Eigen/Dense>

#include "modeling/tessellation/surface_builder.h"

namespace qacc::tess {

// The part of `box` where the surface can be: the cells of a 40³ scan whose corners change
// sign (or come within a cell's gradient bound of zero), inside the clip planes' reach.
Eigen::AlignedBox3d surfaceBox(const Quadric& q, const Eigen::AlignedBox3d& box, const std::vector<HalfSpace>& planes);

// Marching tetrahedra over `box` with about n cells along the longest side.
void marchQuadricBox(SurfaceBuilder& sb, const Quadric& q, const Eigen::AlignedBox3d& box, int n);

// The piece of q (normalised) in `box`, at about `target` triangles: sb.domain must be the
// identity (world points, linear).
void marchQuadricPiece(SurfaceBuilder& sb, const Quadric& q, const Eigen::AlignedBox3d& box,
                       const std::vector<HalfSpace>& planes, int target);

}  // namespace qacc::tess
