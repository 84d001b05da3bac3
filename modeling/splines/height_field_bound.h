// HeightFieldBound: a conservative range of a simplex B-spline height field z = F(x, y)
// (simplex_spline2.h) over a convex polygon of its domain, before any cell is built — a range
// that may be too wide but never misses a value of F (nor of a cell's polynomial, which is F
// continued to the cell's closed polygon). Used for view culling: the prism polygon x [lo, hi]
// holds the surface over the polygon (SimplexSpline2::cells).
//
// The bound assumes nothing of the basis — neither that it sums to one (a partition of unity,
// which knot clouds as large as an edge or explicit "knots" break anywhere in the domain:
// HeightFieldBound.HoldsWhereTheBasisIsNotAPartitionOfUnity finds sums of 1.67 with clouds of
// 0.9 x the shortest edge; the convex hull of the coefficients, the bound before, assumed it
// beyond the clouds' reach from the boundary) nor that it is non-negative. It rests on the
// algebra of the compiled basis alone (simplex_spline_base.h): F(u) = Σ_S 1_S(u) T_S(u), the
// sum over the knot simplices S of the leaves of the basis functions near the polygon, T_S the
// sum of those leaves' c w Π λ — one quadratic for degree <= 2. Over the polygon P:
// - a simplex whose closed hull holds P adds T_S at every point of P (and to every cell's
//   polynomial that meets P's interior), so the held T_S are summed and the sum's exact range
//   over P is taken (corners, extrema along the edges, the stationary point inside);
// - a simplex that P straddles adds T_S or nothing: its range over P ∩ S (P clipped to the
//   closed simplex), widened to 0;
// - a simplex that misses P adds nothing.
// (For degree 3 and 4, each leaf's product of its factors' intervals instead.) Corners within
// a rounding slack (1e-9 of the coordinates) of a simplex's side count as on it: a sliver of
// that width holds no pixel beside the view volume's 2-pixel margin. The sum holds F and every
// cell's polynomial at every point of P, whatever the knots.
//
// The bound is loose over a large polygon (the straddled simplices widen it) and tighter over
// a small one, so mayReach() subdivides: the surface over a polygon may reach the view unless
// the prism of the polygon or of every piece of its recursive cutting misses it; a piece is
// cut along the side of the straddled simplex that widened its range most (or halved across
// its longer side), and a piece with a point of the surface itself in the view (F at its
// centroid) is kept at once.
#pragma once
#include <vector>

#include <Eigen/Dense>

#include "modeling/scene/view_volume.h"
#include "modeling/splines/simplex_spline_base.h"

namespace qacc {

class HeightFieldBound {
 public:
  explicit HeightFieldBound(const SimplexSplineBase<2>& spline) : spline_(spline) {}

  struct Range {
    double lo = 0, hi = 0;
  };
  // The range of F over the convex polygon (its corners, any orientation), padded by a
  // relative 1e-6 of the leaves' magnitudes against rounding in the cells' polynomials.
  Range over(const std::vector<Eigen::Vector2d>& polygon) const;

  // Cuts of a polygon whose prism meets the view before it is kept (on bspline_g0 and g1 at
  // fov 40 to 2 degrees, depth 10 culled at most one triangle fewer than 14, in less time).
  static constexpr int kSubdivisionDepth = 10;
  // False only when the surface over the convex polygon surely misses the view (the prisms of
  // the polygon or of its pieces, cut up to `depth` times, miss it).
  bool mayReach(const std::vector<Eigen::Vector2d>& polygon, const ViewVolume& view,
                int depth = kSubdivisionDepth) const;

 private:
  const SimplexSplineBase<2>& spline_;
  struct Straddle {
    SimplexSplineBase<2>::Affine line;  // a side of a leaf's simplex that crosses the polygon
    bool found = false;
  };
  Range over(const std::vector<Eigen::Vector2d>& polygon, Straddle* straddle) const;
};

}  // namespace qacc
