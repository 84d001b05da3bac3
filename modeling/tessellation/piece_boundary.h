// Whether the triangles of a clipped piece are a proper piece of its surface: every vertex
// inside the region (its clip planes and, when added, the frustum's; within rounding), and
// every open edge (one used by a single surface triangle) on one of the region's planes.
// A parametric grid clipped in parameter space can fail both where the piece is small
// against the grid's cells (a Bernstein-Bézier or B-spline cell on a large quadric): the
// plane's trace is curved in (u, v), a cut point inherits the plane tags of its edge's ends
// and a corner's Newton steps may not converge, so vertices land outside a plane and the
// mesh has holes and rounding slivers inside the piece (tessellation.cpp then refines the
// grid or marches the piece instead). Shared boundaries (shared_boundaries.h) can only be
// stitched where each piece's boundary lies on its planes.
#pragma once
#include <cstddef>
#include <vector>

#include "modeling/geometry/half_space.h"
#include "modeling/tessellation/tessellation.h"

namespace qacc::tess {

struct PieceBoundary {
  std::size_t outside = 0;         // vertices outside a plane by more than rounding
  std::size_t off_plane_edges = 0; // open edges on none of the planes (holes, slivers)
  std::size_t defects() const { return outside + off_plane_edges; }
};

// The first `surface` triangles of `mesh` (the rest are caps) against `planes`.
PieceBoundary checkPieceBoundary(const TriangleMesh3& mesh, std::size_t surface, const std::vector<HalfSpace>& planes);

// x lies on h within rounding (relative to the size of x and of the plane's coefficients).
bool onPlaneWithinRounding(const HalfSpace& h, const Eigen::Vector3d& x);

}  // namespace qacc::tess
