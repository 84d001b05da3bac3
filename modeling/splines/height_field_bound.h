// HeightFieldBound: a conservative range of a simplex B-spline height field z = F(x, y)
// (simplex_spline2.h) over a convex polygon of its domain, before any cell is built — a range
// that may be too wide but never misses a value of F (nor of a cell's polynomial, which is F
// continued to the cell's closed polygon). Used for view culling: the prism polygon x [lo, hi]
// holds the surface over the polygon (SimplexSpline2::cells).
//
// Two bounds, each safe on its own:
// - Convex hull: where the basis is a partition of unity, F is a convex combination of the
//   coefficients of the basis functions not zero there, so it lies within their min and max.
//   The partition of unity holds on the triangulation except within the knot clouds' reach
//   of its boundary (simplex_spline_base.h: a basis function is supported within the reach
//   of its simplex, so beyond it from the boundary no function of a triangle outside the
//   complex could be missing); the polygon qualifies when every point of it lies farther
//   than the reach from every boundary edge (an edge of one triangle only).
// - Interval: anywhere else, F = Σ c N with N a sum over the leaves of the compiled basis of
//   weight x Π λ(u), λ affine; over the polygon each λ lies between its values at the
//   polygon's corners, so the sum of the products' intervals, each widened to 0 (the leaf
//   adds nothing where the polygon leaves its simplex), bounds F with no assumption on Σ N
//   (loose, but only the polygons near the boundary use it).
// The range is padded by a relative 1e-6 against rounding in the cells' polynomials.
#pragma once
#include <array>
#include <vector>

#include <Eigen/Dense>

#include "modeling/splines/simplex_spline_base.h"

namespace qacc {

class HeightFieldBound {
 public:
  explicit HeightFieldBound(const SimplexSplineBase<2>& spline);

  struct Range {
    double lo = 0, hi = 0;
    bool convexHull = false;  // the convex-hull bound was used (else the interval bound)
  };
  // The range of F over the convex polygon (its corners, any orientation).
  Range over(const std::vector<Eigen::Vector2d>& polygon) const;

 private:
  const SimplexSplineBase<2>& spline_;
  double reach_;
  std::vector<std::array<Eigen::Vector2d, 2>> boundary_;  // edges used by one triangle only
  bool farFromBoundary(const std::vector<Eigen::Vector2d>& polygon) const;
};

}  // namespace qacc
