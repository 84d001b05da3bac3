// The extent of a clipped quadric piece along coordinate axes: the exact extremes of x, y
// (and z) over (surface ∩ polytope), or over ({f <= 0} ∩ polytope) for a solid. A linear
// function is extreme on that set among finitely many points (Lagrange), each family a
// line (two planes, since ∇f is affine) cut with the quadric, one stable quadratic each:
//  (a) surface points where ∇f is parallel to the axis;
//  (b) points of each face's conic where ∇f, the face normal and the axis are coplanar;
//  (c) each edge of the polytope against the surface;
//  the singular point of a cone and, for solids, the polytope vertices inside f <= 0.
// Used by the window-space screen box of the renderers (raster/pixel/window_primitive.h,
// axes x and y inside the view volume) and by the world-space bounds of a primitive
// (primitive_bounds.h, all three axes).
#pragma once
#include <cstddef>
#include <vector>

#include <Eigen/Dense>
#include <Eigen/Geometry>

namespace qacc {

// Planes of a polytope P known not to meet the piece (the caller knows the piece lies inside
// each by a margin far above insidePolytope's tolerance, e.g. from bounds found before): no
// point of the surface within that tolerance of P lies on them, so their faces' and edges'
// candidate lines (b) and (c) cannot add one and are not cut. Bit j stands for P[first + j].
struct UnreachablePlanes {
  std::size_t first = 0;
  unsigned mask = 0;
  bool has(std::size_t i) const { return i >= first && i - first < 32 && ((mask >> (i - first)) & 1u) != 0; }
};

// Extent of the candidates for the first `axes` coordinate axes (2: x and y; 3: x, y and
// z) of the piece of quadric Q inside the polytope {X : p·(X, 1) <= 0 for p in P}; `ref` is
// a point near the region (it anchors the candidate lines). Empty when the piece is empty.
// The polytope must be bounded (add bounding planes): only then is the extent exact.
// `unreachable` planes' lines are left out: the same box when the planes are as said.
Eigen::AlignedBox3d pieceExtent(const Eigen::Matrix4d& Q, const std::vector<Eigen::Vector4d>& P, bool solid,
                                const Eigen::Vector3d& ref, int axes, UnreachablePlanes unreachable = {});

// Adds to `ext` the candidates of coordinate axis `ax` (the surface points where ∇f is
// parallel to it, and those of each face's conic), the only ones pieceExtent(..., axes)
// has that pieceExtent(..., ax) lacks when ax = axes - 1: the z extent of a piece whose x
// and y extent is known costs only the z candidates. The box equals pieceExtent's: the
// same points, extended in another order (a box's minimum and maximum do not depend on it).
void addAxisCandidates(const Eigen::Matrix4d& Q, const std::vector<Eigen::Vector4d>& P, const Eigen::Vector3d& ref,
                       int ax, Eigen::AlignedBox3d& ext, UnreachablePlanes unreachable = {});

// Vertices of the polytope P ∩ {plane = 0} (all vertices of P when plane is null), each
// inside P within a relative tolerance of 1e-9.
std::vector<Eigen::Vector3d> polytopeVertices(const std::vector<Eigen::Vector4d>& P, const Eigen::Vector4d* plane);

// True when v lies in P within a relative tolerance of 1e-9.
bool insidePolytope(const std::vector<Eigen::Vector4d>& P, const Eigen::Vector3d& v);

}  // namespace qacc
