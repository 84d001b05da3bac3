// The caps of a solid primitive: on each plane of its region (its clip planes, the view
// frustum's when that bounds it), the polygon bounded by the surface's cut edges on that
// plane (surface_builder.h), closed along the lines where two planes meet, or the whole
// face when the surface does not cross it and its corners are inside the solid;
// triangulated by ear clipping in the plane (a fan from its centroid when no ear is found). The cut edges are shared exactly, so a primitive's mesh is
// watertight.
#pragma once
#include <cstddef>
#include <vector>

#include "modeling/tessellation/surface_builder.h"

namespace qacc::tess {

// Cap on plane h from its oriented boundary segments: chains are followed end to start;
// an open chain (cut by another clip plane j) is closed along the line h ∩ j to the next
// chain start on that line; each loop is triangulated by ear clipping in the plane.
void buildCap(std::size_t k, const std::vector<CapSegment>& segs, const std::vector<HalfSpace>& planes,
              const std::vector<Vector3d>& polytope, const Quadric& q, TriangleMesh3& mesh);

}  // namespace qacc::tess
