// What the simplex B-splines of any dimension share (digest §3; SimplexSpline2 for height
// fields, SimplexSpline3 for volumes): knot clouds, knot sets, the DMS recursion, values,
// local polynomials and control coefficients, written once over the dimension D.
//
// Every vertex i of the simplicial complex carries a knot cloud t_i,0..t_i,n with
// t_i,0 = the vertex. For a simplex I = (i0..iD) and a multi-index |β| = n, the knot set
// V^I_β = {t_i0,0..β0, ..., t_iD,0..βD} (n + D + 1 knots) defines the simplex spline
//   M(u | v0..vD) = 1_[v0..vD)(u) / |d(v0..vD)|     (d = D! x volume, half-open hull),
//   M(u | V) = Σ_j λ_j(u) M(u | V \ v_j)            (λ: barycentric coordinates of u in the
//                                                    (D+1)-subset of V of largest |d|),
// the normalised basis N^I_β = |d(t_i0,β0, ..., t_iD,βD)| M(u | V^I_β) and the spline
// F(u) = Σ_I Σ_β c_I,β N^I_β(u). The half-open rule: a point on a simplex boundary belongs
// to the side reached by an infinitesimal step along a fixed generic direction, so the basis
// is a partition of unity at every point, boundaries included.
//
// The recursion depends on u only through the leaves' indicator functions, so it is
// compiled once per basis function ("geometry-only precomputation", digest §3): the
// (D+1)^n leaves, each a knot simplex (its barycentric forms, for the half-open test), a
// weight and the n affine factors λ met on the way down. A value is then a sum over the
// leaves containing u of weight x Π λ(u), and the polynomial of F around u the same sum
// with the λ kept as affine polynomials. Basis functions are found through a grid of their
// support boxes, so evaluation costs what the few functions not zero at u cost.
#pragma once
#include <array>
#include <cstddef>
#include <vector>

#include <Eigen/Dense>

#include "modeling/algebraic/polynomial3.h"

namespace qacc {

template <int D>
class SimplexSplineBase {
 public:
  using Vec = Eigen::Matrix<double, D, 1>;
  using Box = Eigen::AlignedBox<double, D>;
  using Simplex = std::array<int, D + 1>;  // vertex indices
  using Beta = std::array<int, D + 1>;     // multi-index, |β| = degree

  int degree() const { return n_; }
  const std::vector<Vec>& vertices() const { return verts_; }
  const std::vector<Simplex>& simplices() const { return simplices_; }
  // |β| = n in descending lexicographic order (BBTetra's order for D = 3).
  static std::vector<Beta> multiIndices(int n);
  // The leaves the compiled basis of `simplices` simplices at degree n holds, priced before it
  // is compiled: simplices x C(n + D, D) basis functions x (D + 1)^n leaves each (the recursion
  // drops one of the D + 1 knots of the chosen simplex per level, n levels from n + D + 1 knots
  // down to D + 1). Exact for generic knots (G1 clouds); an upper bound when knots coincide
  // (G0), where a branch whose knots lie in a hyperplane ends early. Saturates at SIZE_MAX.
  static std::size_t basisLeafBound(std::size_t simplices, int degree);

  Vec knot(int vertex, int k) const {
    return k == 0 ? verts_[std::size_t(vertex)] : knots_[std::size_t(vertex)][std::size_t(k) - 1];
  }
  // The knot set V^I_β and the lower set U^I_β = V^I_β without t_i0,β0, ..., t_iD,βD.
  std::vector<Vec> knotSet(std::size_t simplex, const Beta& b) const;
  std::vector<Vec> lowerSet(std::size_t simplex, const Beta& b) const;

  double basis(std::size_t simplex, const Beta& b, const Vec& u) const;  // N^I_β(u)
  // Coefficients c[simplex][index of β in multiIndices(n)].
  void setCoefficients(std::vector<std::vector<double>> c);
  const std::vector<std::vector<double>>& coefficients() const { return coef_; }
  double eval(const Vec& u) const;
  // The single polynomial of F around the interior point `probe` (in x, y[, z]).
  Polynomial3 localPolynomial(const Vec& probe) const;

  // Coefficients reproducing a polynomial p of degree <= n exactly: c_I,β = blossom of p at
  // the lower knot set U^I_β (Marsden identity / DMS polar form). Implemented for n <= 2.
  std::vector<std::vector<double>> blossomCoefficients(const Polynomial3& p) const;
  // Coefficients sampling a function at the Greville points (mean of U^I_β; the simplex's
  // centroid for n = 0).
  std::vector<std::vector<double>> grevilleCoefficients(const Polynomial3& h) const;
  // Coefficients of the blossoms at U^I_β of h's second-order Taylor polynomial at the
  // Greville point (a quasi-interpolant: exact for quadratics, O(h³) error otherwise).
  // Implemented for n <= 2.
  std::vector<std::vector<double>> taylorCoefficients(const Polynomial3& h) const;

  // Optional display domain (an axis-aligned box): cells are clipped to it. The partition of
  // unity, hence polynomial reproduction, holds on the complex except within the knot
  // clouds' reach of its boundary (knotReach()).
  void setDomain(const Box& d) { domain_ = d; }
  const Box& domain() const { return domain_; }
  // The largest distance of a knot from its vertex.
  double knotReach() const;

 // The compiled basis (see the file comment), for the cell decompositions.
  struct Affine {
    Vec a;
    double b;
    double at(const Vec& u) const { return a.dot(u) + b; }
  };
  struct Leaf {
    std::array<Affine, D + 1> bary;  // barycentric forms of the leaf's knot simplex
    double weight;                   // normalisation / |d(leaf)|
    std::array<int, D + 1> knots;    // its knots, as knotId
  };
  struct Basis {
    std::size_t simplex = 0, beta = 0;
    Box support;                   // bounding box of the knot set
    std::vector<Leaf> leaves;
    std::vector<Affine> factors;  // n per leaf, leaf after leaf
    double value(const Vec& u, int n) const;
  };
  const std::vector<Basis>& basisFunctions() const { return basis_; }
  // Leaves of the compiled basis, summed over the basis functions (<= basisLeafBound).
  std::size_t leafCount() const;
  double coefficientOf(const Basis& b) const { return coef_[b.simplex][b.beta]; }
  // Indices (ascending) of the basis functions whose support box meets `box`.
  std::vector<std::size_t> basisNear(const Box& box) const;
  // Half-open membership in a leaf's simplex.
  static bool inside(const Leaf& l, const Vec& u);
  // t_vertex,k as one number.
  int knotId(int vertex, int k) const { return vertex * (n_ + 1) + k; }
  Vec knotById(int id) const { return knot(id / (n_ + 1), id % (n_ + 1)); }

 protected:
  SimplexSplineBase(const char* name, int degree, int maxDegree, std::vector<Vec> vertices,
                    std::vector<Simplex> simplices, std::vector<std::vector<Vec>> knots);
  std::size_t basisIndex(std::size_t simplex, std::size_t beta) const { return simplex * betas_.size() + beta; }
  // rule(U, ξ) for every (I, β): U^I_β and the Greville point, in 3D (z = 0 for D = 2).
  template <class Rule>
  std::vector<std::vector<double>> coefficientsBy(Rule rule) const;
  // localPolynomial with the candidate basis functions given (a superset of those not zero
  // at the probe, e.g. basisNear of a box around it).
  Polynomial3 localPolynomial(const Vec& probe, const std::vector<std::size_t>& candidates) const;

  int n_;
  std::vector<Vec> verts_;
  std::vector<Simplex> simplices_;
  std::vector<std::vector<Vec>> knots_;
  std::vector<std::vector<double>> coef_;
  Box domain_;  // empty: the whole complex

 private:
  std::vector<Beta> betas_;
  std::vector<Basis> basis_;
  // Uniform grid over the support boxes.
  Box gridBox_;
  Eigen::Array<int, D, 1> gridDims_;
  Eigen::Array<double, D, 1> gridCell_;
  std::vector<std::vector<std::size_t>> grid_;
  void compile();
};

// Knot clouds: "G0" (g1 = false) puts every knot on its vertex (Bernstein-Bézier pieces,
// C0); "G1" spreads t_i,1..t_i,n at distance up to `radius` x (shortest incident edge)
// around vertex i in fixed, irregular directions (generic knots, C^(n-1)).
template <int D>
std::vector<std::vector<Eigen::Matrix<double, D, 1>>> simplexKnotClouds(
    const std::vector<Eigen::Matrix<double, D, 1>>& vertices, const std::vector<std::array<int, D + 1>>& simplices,
    int degree, bool g1, double radius);

extern template class SimplexSplineBase<2>;
extern template class SimplexSplineBase<3>;

}  // namespace qacc
