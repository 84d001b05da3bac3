// Simplex B-splines (Dahmen-Micchelli-Seidel, digest §3) over a triangulation (s = 2,
// functional height fields z = F(x, y)) or a tetrahedralisation (s = 3, volumes
// w = F(x, y, z) whose surface is F = 0), of degree n (used with n = 2).
//
// Every vertex i of the simplicial complex carries a knot cloud t_i,0..t_i,n with
// t_i,0 = the vertex. For a simplex I = (i0..is) and a multi-index |β| = n, the knot set
// V^I_β = {t_i0,0..β0, ..., t_is,0..βs} (n + s + 1 knots) defines the simplex spline
//   M(u | v0..vs) = 1_[v0..vs)(u) / |d(v0..vs)|     (d = s! x volume, half-open hull),
//   M(u | V) = Σ_j λ_j(u) M(u | V \ v_j)            (λ: barycentric coordinates of u in a
//                                                    non-degenerate (s+1)-subset of V),
// the normalised basis N^I_β = |d(t_i0,β0, ..., t_is,βs)| M(u | V^I_β) and the spline
// F(u) = Σ_I Σ_β c_I,β N^I_β(u). With generic knots F is C^(n-1) (G1 surfaces for n = 2);
// knots that coincide with the vertices give the Bernstein-Bézier pieces joined C^0 (G0).
// The half-open rule: a point on a simplex boundary belongs to the side reached by moving
// it an infinitesimal step along a fixed generic direction, so the basis is a partition of
// unity at every point, boundaries included.
//
// Conversion for the hardware: F is one polynomial inside each cell of the arrangement of
// the segments (s = 2) between knots that occur together in a knot set. Cells are built by
// splitting convex polygons (the domain's triangles) by the supporting line of every such
// segment that crosses them; each cell's polynomial is obtained by running the recursion
// symbolically (λ_j are affine polynomials) at an interior point, and the cell is emitted
// as the quadric z - p(x, y) = 0 clipped by the vertical planes of its edges (one plane per
// line, built once; neighbours use its opposite()).
#pragma once
#include <array>
#include <vector>

#include <Eigen/Dense>

#include "modeling/polynomial3.h"
#include "modeling/primitive.h"

namespace qacc {

class SimplexSpline2 {
 public:
  using Vec = Eigen::Vector2d;
  using Beta = std::array<int, 3>;

  // knots[i] = t_i,1..t_i,n (n points; t_i,0 = vertices[i] is implicit).
  SimplexSpline2(int degree, std::vector<Vec> vertices, std::vector<std::array<int, 3>> triangles,
                 std::vector<std::vector<Vec>> knots);

  int degree() const { return n_; }
  const std::vector<Vec>& vertices() const { return verts_; }
  const std::vector<std::array<int, 3>>& triangles() const { return tris_; }
  static std::vector<Beta> multiIndices(int n);  // |β| = n, fixed order

  Vec knot(int vertex, int k) const { return k == 0 ? verts_[std::size_t(vertex)] : knots_[std::size_t(vertex)][std::size_t(k) - 1]; }
  // The knot set V^I_β and the lower set U^I_β = V^I_β without t_i0,β0, t_i1,β1, t_i2,β2.
  std::vector<Vec> knotSet(std::size_t tri, const Beta& b) const;
  std::vector<Vec> lowerSet(std::size_t tri, const Beta& b) const;

  double basis(std::size_t tri, const Beta& b, const Vec& u) const;  // N^I_β(u)
  // Coefficients c[tri][index of β in multiIndices(n)].
  void setCoefficients(std::vector<std::vector<double>> c) { coef_ = std::move(c); }
  const std::vector<std::vector<double>>& coefficients() const { return coef_; }
  double eval(const Vec& u) const;

  // The single polynomial of F around the interior point `probe` (as a Polynomial3 in x, y).
  Polynomial3 localPolynomial(const Vec& probe) const;

  // Coefficients reproducing a polynomial p of degree <= n exactly: c_I,β = blossom of p at
  // the lower knot set U^I_β (Marsden identity / DMS polar form). Implemented for n <= 2.
  std::vector<std::vector<double>> blossomCoefficients(const Polynomial3& p) const;
  // Coefficients sampling a height function at the Greville points (mean of U^I_β).
  std::vector<std::vector<double>> grevilleCoefficients(const Polynomial3& h) const;

  struct Cell {
    std::vector<Vec> polygon;           // convex, counter-clockwise
    std::vector<HalfSpace> edges;       // vertical planes (z coefficient 0), keep the cell
    Polynomial3 poly;                   // F inside the cell
  };
  // Optional display domain (an axis-aligned rectangle): cells are clipped to it. The
  // partition of unity, hence polynomial reproduction, holds on the triangulation except
  // within the knot clouds' reach of its boundary, so a domain inset from the boundary
  // shows only the well-formed part of the spline.
  void setDomain(const Eigen::AlignedBox2d& d) { domain_ = d; }
  const Eigen::AlignedBox2d& domain() const { return domain_; }

  // Convex cells covering the triangulation (∩ domain) where F is one polynomial.
  std::vector<Cell> cells() const;
  // Height-field primitives z = F(x, y): one quadric per cell, clipped by its edges.
  std::vector<Primitive> toPrimitives(int material = 0, int object = 0) const;

 private:
  int n_;
  std::vector<Vec> verts_;
  std::vector<std::array<int, 3>> tris_;
  std::vector<std::vector<Vec>> knots_;
  std::vector<std::vector<double>> coef_;
  Eigen::AlignedBox2d domain_;  // empty: the whole triangulation
};

// Knot clouds for a triangulation: "G0" puts every knot on its vertex (Bernstein-Bézier
// pieces, C0); "G1" spreads t_i,1..t_i,n at distance `radius` x (shortest incident edge)
// around vertex i in fixed, irregular directions (generic knots, C1 for n = 2).
std::vector<std::vector<Eigen::Vector2d>> knotClouds(const std::vector<Eigen::Vector2d>& vertices,
                                                    const std::vector<std::array<int, 3>>& triangles,
                                                    int degree, bool g1, double radius = 0.15);

}  // namespace qacc
