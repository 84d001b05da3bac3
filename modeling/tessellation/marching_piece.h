// Quadric pieces without a parametric grid (hyperbolic paraboloid, parabolic and hyperbolic
// cylinders, the degenerate types, and small clipped pieces a grid misses): marching
// tetrahedra (modeling/algebraic/marching_tetrahedra.h) over the part of the region's box
// where the surface can be, edge points refined onto the surface by Newton steps along the
// gradient, the triangles clipped by the piece's planes through the surface builder.
#pragma once
#include <vector>

#include <Eigen/Dense>

#include "modeling/tessellation/surface_builder.h"

namespace qacc {
class ScreenView;
}

namespace qacc::tess {

// The part of `box` where the surface can be: the cells of a 40³ scan whose corners change
// sign (or come within a cell's gradient bound of zero), inside the clip planes' reach.
Eigen::AlignedBox3d surfaceBox(const Quadric& q, const Eigen::AlignedBox3d& box, const std::vector<HalfSpace>& planes);

// Marching tetrahedra over `box` with about n cells along the longest side.
void marchQuadricBox(SurfaceBuilder& sb, const Quadric& q, const Eigen::AlignedBox3d& box, int n);

// Cells along the longest side of `box` for a projected chord error of at most `epsilon`
// pixels: the vertices of a coarse pass (on the surface, kept by `planes`, on screen) give
// the largest projected principal curvature A = max s κ (s pixels per world unit,
// screen_error.h; κ the larger |principal curvature| of the quadric there); a Kuhn cell of
// side h has triangle edges up to h√3 and triangles of circumradius up to h, so their chord
// error is at most κ h² / 2 and h = √(2 ε / A) (times a margin), divided by `scale`. The
// count is capped so that the surface's cells stay within about `max_triangles` triangles.
int marchingCellsForPixelError(const Quadric& q, const Eigen::AlignedBox3d& box, const std::vector<HalfSpace>& planes,
                               const ScreenView& view, double epsilon, double scale, int max_triangles);

// The piece of q (normalised) in `box`, at about `target` triangles: sb.domain must be the
// identity (world points, linear).
void marchQuadricPiece(SurfaceBuilder& sb, const Quadric& q, const Eigen::AlignedBox3d& box,
                       const std::vector<HalfSpace>& planes, int target);

}  // namespace qacc::tess
