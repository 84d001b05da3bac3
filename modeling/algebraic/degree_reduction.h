// Piecewise degree reduction of an algebraic surface f(x, y, z) = 0 of any degree to
// quadric pieces (digest §4, thesis ch. 5): the box is cut into a Kuhn tetrahedral mesh,
// f is converted to its degree-n Bernstein-Bézier form on every tetrahedron and reduced to
// degree 2 by iterated Petersen (BBTetra::reducedTo), and each kept cell emits its quadric
// clipped by the tetrahedron's 4 faces (BBQuadric::toPrimitive: a face shared by two cells
// is one plane and its opposite()). Vertex and edge coefficients are computed once per
// mesh vertex / edge and shared by every tetrahedron around it, so neighbouring pieces
// agree exactly on their common face (G0).
//
// Culling never opens a hole: a cell is dropped only when its degree-n coefficients have
// one strict sign (the true surface misses the cell, convex hull property) AND its reduced
// degree-2 coefficients have that same strict sign (the piece it would emit is empty too).
// A dropped cell therefore contributes nothing to either surface: the culled model renders
// exactly like the full one. (Culling on the reduced coefficients alone would drop cells
// the true surface crosses; culling on the degree-n ones alone would drop non-empty pieces.)
//
// Options: uniform 1 → 8 refinement (Bey's split of every Kuhn tetrahedron = the Kuhn mesh
// of half the spacing, still conforming) until the measured geometric error is below a
// bound; smoothing (each interior vertex coefficient set to the mean of the edge
// coefficients around it, approaching the 4D coplanarity that C1 requires, thesis
// fig. 5.13; G0 is kept since vertex coefficients stay shared); merging of the pieces that
// lie on the same quadric (whole cubes, then boxes of cubes, become one primitive clipped
// by 6 planes) and counting the distinct quadrics.
#pragma once
#include <vector>

#include <Eigen/Dense>

#include "modeling/algebraic/polynomial3.h"
#include "modeling/geometry/primitive.h"
#include "modeling/scene/view_volume.h"

namespace qacc {

struct DegreeReductionOptions {
  int level = 4;              // cubes per axis of the Kuhn mesh
  double refine_error = 0.0;  // > 0: double the level until the geometric error is below it
  int max_level = 64;         // refinement stops here
  bool smooth = false;
  bool merge = false;
  bool cull = true;           // false: emit every cell (for checking that culling changes nothing)
  int material = 0;
  int object = 0;
  // View culling (loader/view_culling.h): cells whose tetrahedron misses this volume (in the
  // polynomial's frame) are neither emitted nor, at a fixed level, reduced — only the cells
  // of the cubes around the visible ones are (they own the coefficients the visible cells
  // share), so the build time falls with the view. The kept pieces are exactly the
  // unculled model's. With `merge`, and while `refine_error` chooses the level (the error
  // is measured on the whole model), every cell is still built; null: no view culling.
  const ViewVolume* view = nullptr;
};

// Sampled distance between the pieces and the true surface (world units): points on each
// kept piece (roots of its quadric along 13 segments per cell) projected onto f = 0 by
// Newton steps along ∇f, and points of f = 0 (roots along the same segments) measured to
// the cell's quadric to first order (|q| / |∇q|).
struct GeometricError {
  double max_piece_to_surface = 0;
  double mean_piece_to_surface = 0;
  double max_surface_to_piece = 0;
  double mean_surface_to_piece = 0;
  int samples = 0;
  double max() const { return std::max(max_piece_to_surface, max_surface_to_piece); }
};

struct DegreeReductionResult {
  std::vector<Primitive> primitives;
  int level = 0;              // final level (after refinement)
  int cells = 0;              // tetrahedra in the mesh
  int kept_cells = 0;         // cells not culled
  int view_culled_cells = 0;  // cells whose tetrahedron misses the view (options.view)
  int built_cells = 0;        // cells whose Bernstein form was computed and reduced
  int distinct_quadrics = 0;  // among the kept pieces, up to scale (relative tolerance 1e-9)
  int merged_groups = 0;      // primitives made of more than one cell (merge)
  GeometricError error;       // of the final model
};

DegreeReductionResult reduceAlgebraic(const Polynomial3& f, const Eigen::AlignedBox3d& box,
                                      const DegreeReductionOptions& options);

}  // namespace qacc
