// A piece's mesh made to end on the shared polylines of its shared boundaries
// (shared_boundaries.h, shared_polyline.h): every surface triangle with a vertex on one of the
// piece's shared planes is removed, and the strip between what is left — the chains of edges
// between kept and removed triangles — and the polylines is triangulated again:
//  - the polylines, joined end to end where their ends are equal, form the piece's new
//    boundary paths (a closed loop for a piece whose boundary is all shared);
//  - each such path is paired with the kept mesh's inner chain nearest to it (a loop with a
//    loop, an open path with the open chain whose ends are nearest its ends), and the two
//    are zipped: from one end, a triangle at a time, advancing on the side whose next vertex
//    comes first by fraction of arc length;
//  - a closed loop with nothing kept inside it (a piece whose triangles all touch its shared
//    planes) is fanned from its centroid moved onto the surface.
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
#include "modeling/tessellation/tessellation.h"

namespace qacc::tess {

// False, with the mesh unchanged, when the polylines or the kept chains do not pair up (a
// junction of more than two, different counts of paths and chains, an open path with no kept
// chain).
bool zipBoundaryStrip(TriangleMesh3& mesh, std::size_t& surface, const std::vector<HalfSpace>& sharedPlanes,
                      const std::vector<std::vector<Eigen::Vector3d>>& polylines, const Quadric& q);

}  // namespace qacc::tess
