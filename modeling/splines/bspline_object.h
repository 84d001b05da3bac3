// Scene object "bspline" (design §5-6): a degree-2 simplex B-spline, either a height field
// z = F(x, y) (simplex_spline.h, "dimension": 2, the default) or a volume w = F(x, y, z)
// shown as its surface F = 0 (simplex_spline3.h, "dimension": 3), converted to clipped
// quadric cells.
//
//   {"type": "bspline", "degree": 2,
//    "grid": {"min": [-2, -2], "max": [2, 2], "n": 4},        (or "vertices" + "triangles")
//    "continuity": "G1", "knot_radius": 0.2,                    (or explicit "knots")
//    "height": "0.5 (x^2 + y^2) - 0.1 x^4", "params": {...},    (or "coefficients")
//    "domain": [[-1.5, -1.5], [1.5, 1.5]]}
//
//   {"type": "bspline", "dimension": 3, "degree": 2,
//    "grid": {"min": [-1.2, -1.2, -1.2], "max": [1.2, 1.2, 1.2], "n": 3},  (or "vertices" + "tetrahedra")
//    "continuity": "G1", "knot_radius": 0.2,                    (or explicit "knots")
//    "field": "x^2 + y^2 + z^2 - 0.5", "params": {...},        (or "coefficients")
//    "domain": [[-1, -1, -1], [1, 1, 1]]}
//
// grid: a regular n x n triangulation of the rectangle (each square cut along its
// diagonal), or the Kuhn tetrahedralisation of n x n x n boxes of the box ("n" may also be
// [nx, ny, nz]; 6 tetrahedra per box, kuhn_mesh.h); vertices/triangles/tetrahedra: an explicit complex ([x, y] or
// [x, y, z] points, index triples or quadruples). continuity: "G1" (generic knot clouds
// of relative radius knot_radius, default 0.2: C1) or "G0" (knots on the vertices:
// Bernstein-Bézier pieces joined C0); knots: explicit clouds, one list of `degree` points
// per vertex. height (x, y) / field (x, y, z): a polynomial whose samples give the control
// coefficients: "sampling": "greville" (default: its values at the Greville points) or
// "taylor" (blossoms of its second-order Taylor polynomial at the Greville points: exact
// for quadratics, closer for the rest; degree <= 2); coefficients: explicit, one list per simplex over the
// multi-indices |β| = degree in descending lexicographic order ((2,0,0), (1,1,0), (1,0,1),
// (0,2,0), (0,1,1), (0,0,2) for triangles; (2,0,0,0), (1,1,0,0), ... (0,0,0,2), 10 numbers,
// for tetrahedra). domain: the displayed box. Default for height fields: the
// triangulation's bounding box, inset by its longest edge for G1 (the boundary zone where
// the knot clouds leave the partition of unity incomplete is not shown); for volumes: the
// bounding box inset by the knot reach (the largest distance of a knot from its vertex;
// 0 for G0), beyond which the basis is a partition of unity. Both forms take degree 1 or
// 2 (every cell is a quadric). Volumes take "cull" (default true; false emits every cell, for measurements:
// the image is the same); `qacc info` prints their cell statistics and build time.
#pragma once
#include <vector>

#include "modeling/loader/object_registry.h"
#include "modeling/splines/simplex_spline3.h"

namespace qacc {

std::vector<Primitive> buildBspline(const JsonNode& o, ObjectContext& ctx);
// The spline of a volume object ("dimension": 3) as buildBspline reads it, domain and
// coefficients set: its crossedCells() are the object's primitives. A basis priced over
// limits.max_cells is refused before it is compiled.
SimplexSpline3 readBsplineVolume(const JsonNode& o, const Limits& limits = Limits{});

}  // namespace qacc
