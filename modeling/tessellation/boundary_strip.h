// A piece's mesh made to end on the shared polylines of its shared boundaries
// (shared_boundaries.h, shared_polyline.h): every surface triangle with a vertex on one of the
// piece's shared planes is removed, and the strip between what is left — the chains of edges
// between kept and removed triangles — and the polylines is triangulated again:
//  - the polylines, joined end to end where their ends are equal, form the piece's new
//    boundary paths (a closed loop for a piece whose boundary is all shared); a segment found
//    an even number of times in them (twice: on two of the piece's planes, a sliver between
//    two neighbours that end on one chord) is left out, so is a spur (a segment from a point
//    ending three or more to one ending it alone: a neighbour's arc the piece reaches only at
//    a corner), and a piece left with none draws no surface when all its vertices and
//    triangle centroids lie within the tolerance (or kMergeEnds) of those chords — refused
//    otherwise; with no open kept chain and no edge of its own on an unshared plane, an open
//    path whose ends are within kMergeEnds is closed (an arc too short for its ends to be
//    found, missing alike on both sides);
//  - each such path is paired with the kept mesh's inner chain nearest to it (a loop with a
//    loop, an open path with the open chain whose ends are nearest its ends), and the two
//    are zipped: from one end, a triangle at a time, advancing on the side whose next vertex
//    comes first by fraction of arc length;
//  - a closed loop with nothing kept inside it (a piece whose triangles all touch its shared
//    planes) is triangulated with the least total area (fanned from its centroid moved onto
//    the surface beyond kMaxLoopPoints); here and below, a loop's triangulation has as few
//    triangles as it can with all three vertices on one shared plane (such a triangle lies in
//    the plane, off the surface, and the piece across, on the same vertices, would draw it
//    too), the least total area among those;
//  - when the paths do not pair up so (a piece whose kept triangles do not separate its
//    shared planes, or with none kept and an outer boundary): the open paths are joined to
//    the chains of what is left — the kept chains and the piece's own edges on planes no
//    other piece shares — end to nearest end (a chain's end within kMergeEnds of the path's
//    becomes it), and each loop this closes is triangulated with the least total area;
//    two closed paths and no other (a band of surface across the region) are zipped to each
//    other, none of the piece's own triangles kept;
//  - when neither closes the strip (a kept region whose chains do not pair with the paths,
//    a loop that does not close), or the strip stays over the tolerance after its refinement
//    (below), the whole piece is rebuilt so: every surface triangle removed, its polylines and
//    its own edges on unshared planes triangulated and refined; of the two, the one with the
//    smaller error is kept (a closed mesh over the tolerance rather than a crack: the
//    tessellation's report measures the error on the final triangles).
// The polyline vertices are used as given, so two pieces zipped onto one polyline share its
// vertices bit for bit and every edge of it is used by one triangle on each side. Normals:
// the kept vertices keep theirs, the new ones get the surface's gradient, turned like the
// nearest kept one; each new triangle is wound like the kept ones (by its normals).
// Caps (the triangles after the surface ones) are left as they are.
#pragma once
#include <cstddef>
#include <vector>

#include <Eigen/Dense>

#include "modeling/geometry/half_space.h"
#include "modeling/geometry/quadric.h"
#include "modeling/tessellation/shared_polyline.h"  // PolylineTolerance
#include "modeling/tessellation/tessellation.h"

namespace qacc::tess {

// Longest loop triangulated by least area (its cost grows with the cube of its points).
constexpr std::size_t kMaxLoopPoints = 1200;
// A chain's end this close to a path's end (relative to its distance from the origin, at
// least a unit) is that end: a piece's own corner and the shared one differ by the gap
// between the pieces' surfaces (up to 3e-4 on the torus's reduction pieces).
constexpr double kMergeEnds = 1e-3;
constexpr int kStripRefinements = 24;
// ... nor beyond this many times the triangles it had when first made or that it replaced,
// whichever is more (a tolerance far below what the surface's sampling can show, such as a
// flat piece's chord error of 0, would not stop it).
constexpr std::size_t kStripGrowth = 16;

// Distance from x to the nearest segment of the polylines.
double distanceToSegments(const Eigen::Vector3d& x, const std::vector<std::vector<Eigen::Vector3d>>& polylines);

// False, with the mesh unchanged, when no way closes the strip, not even from nothing kept (a
// junction of more than two, a loop that does not close, holds no polyline or is longer than
// kMaxLoopPoints).
// `tol`: every new triangle whose error (measured at tol.samples as the tessellation's report
// measures it) exceeds it is split, its midpoints moved onto the surface, up to
// kStripRefinements rounds or kStripGrowth times the strip; a triangle no longer than the
// tolerance is not split; the polylines and the kept triangles' edges are never split.
bool zipBoundaryStrip(TriangleMesh3& mesh, std::size_t& surface, const std::vector<HalfSpace>& sharedPlanes,
                      const std::vector<std::vector<Eigen::Vector3d>>& polylines, const Quadric& q,
                      const PolylineTolerance& tol);

}  // namespace qacc::tess
