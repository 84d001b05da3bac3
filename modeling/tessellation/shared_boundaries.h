// Crack-free shared boundaries (tessellation.h): pieces of one object that share a clip
// plane — one has the half-space h, the other exactly h.opposite(), as the modelers build a
// shared face (macropatch cells, B-spline cells, degree-reduction pieces, revolution slabs)
// — meet along the curve where both surfaces cross that plane. Each piece is tessellated on
// its own, so each samples that curve at its own grid's crossings: the two polylines have
// different vertices and the facets crack between them. Here the boundary is made common:
//  1. the vertices of every piece's boundary edges on a shared plane (the cut points, which
//     lie on the curve and on the plane) are collected per plane;
//  2. vertices of the two sides closer than a rounding tolerance (corners found by each
//     piece's own Newton steps) are snapped to one position, the lowest primitive's;
//  3. every boundary vertex of one side that lies inside a boundary edge of the other side
//     (on the segment, not beyond its ends, and no farther from the other piece's surface
//     than from its own: where the quadric pieces meet, not across a gap between them) is
//     inserted into that edge, and the triangles on the edge are split into a fan from
//     their opposite vertex (caps on that edge too).
// Both sides then carry the union of the two samplings, so every shared edge has the same
// vertices on both sides and the mesh has no T-junction there: each edge of a shared
// boundary is used by exactly two triangles. Where the quadric pieces themselves have a
// gap (a piece not G0 with its neighbour) nothing is inserted: the facets keep that gap.
// tessellateScene stitches only the pieces that surely reach the view (piece_in_view.h), so
// that view culling, which removes pieces outside it, changes no kept piece's triangles.
#pragma once
#include <cstddef>
#include <vector>

#include "modeling/geometry/primitive.h"
#include "modeling/tessellation/tessellation.h"

namespace qacc::tess {

struct StitchReport {
  std::size_t shared_planes = 0;      // planes with pieces on both sides
  std::size_t snapped = 0;            // vertices moved onto their neighbour's
  std::size_t inserted = 0;           // vertices inserted into a neighbour's boundary edge
};

// `meshes[i]` is the tessellation of prims[i] (surface triangles first), or null when the
// primitive was not tessellated as a piece (an object drawn by its exact surface). Only
// pieces of the same object are stitched. `surfaceTriangles[i]` (the first triangles of
// meshes[i] that are surface, the rest caps) is updated.
StitchReport stitchSharedBoundaries(const std::vector<Primitive>& prims, const std::vector<TriangleMesh3*>& meshes,
                                    std::vector<std::size_t>& surfaceTriangles);

}  // namespace qacc::tess
