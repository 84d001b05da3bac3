// Simplex B-spline height fields (Dahmen-Micchelli-Seidel, digest §3): s = 2, functional
// surfaces z = F(x, y) of degree n (used with n = 2) over a triangulation. Knot clouds, knot
// sets, the recursion and the coefficients are SimplexSplineBase<2> (simplex_spline_base.h);
// with generic knots F is C^(n-1) (G1 surfaces for n = 2), knots that coincide with the
// vertices give Bernstein-Bézier triangles joined C^0 (G0).
//
// Conversion for the hardware: F is one polynomial inside each cell of the arrangement of
// the segments between knots that occur together in a knot set. Cells are built by
// splitting convex polygons (the domain's triangles) by the supporting line of every such
// segment that crosses them; each cell's polynomial is obtained by running the recursion
// symbolically (λ_j are affine polynomials) at an interior point, and the cell is emitted
// as the quadric z - p(x, y) = 0 clipped by the vertical planes of its edges (one plane per
// line, built once; neighbours use its opposite()).
//
// View culling (`view`, loader/view_culling.h): a domain triangle (clipped to the display
// domain) whose prism — the polygon x the range of F over it (height_field_bound.h) — misses
// the view volume is not cut into cells; every other triangle is cut exactly as without a
// view (a triangle's cells depend only on itself), so the cells kept are the unculled ones.
#pragma once
#include <array>
#include <vector>

#include <Eigen/Dense>

#include "modeling/geometry/primitive.h"
#include "modeling/loader/view_cull_count.h"
#include "modeling/scene/view_volume.h"
#include "modeling/splines/simplex_spline_base.h"

namespace qacc {

class SimplexSpline2 : public SimplexSplineBase<2> {
 public:
  using Vec = Eigen::Vector2d;

  // knots[i] = t_i,1..t_i,n (n points; t_i,0 = vertices[i] is implicit).
  SimplexSpline2(int degree, std::vector<Vec> vertices, std::vector<std::array<int, 3>> triangles,
                 std::vector<std::vector<Vec>> knots)
      : SimplexSplineBase<2>("SimplexSpline2", degree, 4, std::move(vertices), std::move(triangles), std::move(knots)) {}

  const std::vector<std::array<int, 3>>& triangles() const { return simplices(); }

  struct Cell {
    std::vector<Vec> polygon;           // convex, counter-clockwise
    std::vector<HalfSpace> edges;       // vertical planes (z coefficient 0), keep the cell
    Polynomial3 poly;                   // F inside the cell
  };
  // Convex cells covering the triangulation (∩ domain) where F is one polynomial; with a
  // view, only those of the triangles that may meet it (each triangle counted in `count`).
  std::vector<Cell> cells(const ViewVolume* view = nullptr, ViewCullCount* count = nullptr) const;
  // Height-field primitives z = F(x, y): one quadric per cell, clipped by its edges.
  std::vector<Primitive> toPrimitives(int material = 0, int object = 0, const ViewVolume* view = nullptr,
                                      ViewCullCount* count = nullptr) const;
};

// Knot clouds for a triangulation (simplexKnotClouds<2>).
inline std::vector<std::vector<Eigen::Vector2d>> knotClouds(const std::vector<Eigen::Vector2d>& vertices,
                                                           const std::vector<std::array<int, 3>>& triangles,
                                                           int degree, bool g1, double radius = 0.15) {
  return simplexKnotClouds<2>(vertices, triangles, degree, g1, radius);
}

}  // namespace qacc
