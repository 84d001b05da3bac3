// Crack-free shared boundaries (tessellation.h): pieces of one object that share a clip
// plane — one has the half-space h, the other exactly h.opposite(), as the modelers build a
// shared face (macropatch cells, B-spline cells, degree-reduction pieces, revolution slabs)
// — meet along the curve where both surfaces cross that plane. Each piece is tessellated on
// its own; its triangles at the shared planes are then replaced so that both sides end on
// one polyline, by construction:
//  1. per pair of pieces on the two sides of a shared plane (in a canonical order that does
//     not depend on the primitives' numbering: the quadric and plane of the piece whose plane's
//     first non-zero coefficient is positive), the arcs of the curve on their common face, as
//     their ends (shared_polyline.h);
//  2. ends of all arcs closer than a rounding tolerance (a corner where three or more pieces
//     meet, found from different planes) become one point, the lexicographically least;
//  3. each arc sampled once between its two ends, to the tolerance (the pixel error in a
//     view, else the finer of the two pieces' measured chord errors);
//  4. each piece's triangles touching its shared planes removed and the strip to those
//     polylines triangulated again (boundary_strip.h); an arc that two pieces across one
//     plane both end on (they overlap there within the rounding of their corners) counts once
//     on this side: when the two pairs sampled it differently (at a budget, each to its own
//     pieces' chord errors), the finer sampling.
// Both sides then carry the same vertices, bit for bit, on every shared boundary: each edge
// of it is used by exactly two triangles. A plane where an arc's sampling fails is left as
// each piece made it, for all the pieces on it; so is a piece whose strip cannot be closed
// onto its polylines (its neighbours' side of the boundary is then open). Where the quadric
// pieces have a gap (not G0), the strip on the far side bridges it.
// tessellateScene stitches only the pieces that surely reach the view (piece_in_view.h), so
// that view culling, which removes pieces outside it, changes no kept piece's triangles: a
// polyline depends only on its two pieces, a snapped corner only on the ends that meet there.
#pragma once
#include <cstddef>
#include <vector>

#include "modeling/geometry/primitive.h"
#include "modeling/scene/screen_view.h"
#include "modeling/tessellation/tessellation.h"

namespace qacc::tess {

struct StitchReport {
  std::size_t shared_planes = 0;      // planes with pieces on both sides
  std::size_t refused_planes = 0;     // of them, left as the pieces made them
  std::size_t polylines = 0;          // arcs of shared boundaries sampled once
  std::size_t zipped = 0;             // pieces made to end on their polylines
  std::size_t refused_pieces = 0;     // pieces whose strip could not be closed (left as made)
  // Per primitive: true when its surface triangles were rebuilt onto its polylines (its chord
  // and pixel errors must then be measured again, on the mesh as it now is).
  std::vector<char> rebuilt;
};

// How finely the shared curves are sampled: `pixels` of sagitta in `view` when view is set,
// else at most the smaller of the two pieces' `chordError` (world units, measured).
struct SharedBoundarySampling {
  const ScreenView* view = nullptr;
  double pixels = 0;
  std::vector<double> chordError;  // per primitive
  int samples = 6;  // barycentric subdivisions when measuring a rebuilt triangle's error
};

// `meshes[i]` is the tessellation of prims[i] (surface triangles first), or null when the
// primitive is not stitched (an object drawn by its exact surface, a piece not surely in
// view). Only curved, non-solid pieces of the same object are stitched.
// `surfaceTriangles[i]` (the first triangles of meshes[i] that are surface, the rest caps)
// is updated.
StitchReport stitchSharedBoundaries(const std::vector<Primitive>& prims, const std::vector<TriangleMesh3*>& meshes,
                                    std::vector<std::size_t>& surfaceTriangles, const SharedBoundarySampling& sampling);

}  // namespace qacc::tess
