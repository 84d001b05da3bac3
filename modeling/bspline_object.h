// Scene object "bspline" (design §5-6): a degree-2 simplex B-spline height field
// z = F(x, y) (simplex_spline.h) converted to clipped quadric cells.
//
//   {"type": "bspline", "degree": 2,
//    "grid": {"min": [-2, -2], "max": [2, 2], "n": 4},        (or "vertices" + "triangles")
//    "continuity": "G1", "knot_radius": 0.2,                    (or explicit "knots")
//    "height": "0.5 (x^2 + y^2) - 0.1 x^4", "params": {...},    (or "coefficients")
//    "domain": [[-1.5, -1.5], [1.5, 1.5]]}
//
// grid: a regular n x n triangulation of the rectangle (each square cut along its
// diagonal); vertices/triangles: an explicit triangulation ([x, y] points, index triples).
// continuity: "G1" (generic knot clouds of relative radius knot_radius, default 0.2: C1)
// or "G0" (knots on the vertices: Bernstein-Bézier triangles joined C0); knots: explicit
// clouds, one list of `degree` [x, y] points per vertex. height: a polynomial in x and y
// sampled at the Greville points gives the control coefficients; coefficients: explicit,
// one list of (degree+1)(degree+2)/2 numbers per triangle (β = (2,0,0), (1,1,0), (1,0,1),
// (0,2,0), (0,1,1), (0,0,2) for degree 2). domain: the displayed rectangle (default: the
// triangulation's bounding box, inset by its longest edge for G1 so that the boundary zone
// where the knot clouds leave the partition of unity incomplete is not shown).
#pragma once
#include <vector>

#include "modeling/object_builder.h"

namespace qacc {

std::vector<Primitive> buildBspline(const JsonNode& o, ObjectContext& ctx);

}  // namespace qacc
