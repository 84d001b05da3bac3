// Degree-n Bernstein-Bézier (BB) polynomial on a tetrahedron (digest §2 and §4):
//     f(λ) = Σ_{|α|=n} c_α · n!/(α0! α1! α2! α3!) · λ0^α0 λ1^α1 λ2^α2 λ3^α3
// with λ the barycentric coordinates of the point in (V0, V1, V2, V3). Multi-index α
// component a goes with vertex Va (as in modeling/bb_quadric.h, whose 2x2 coefficient
// matrix C is this class's degree-2 case: C(a,a) = c_{2ea}, C(a,b) = c_{ea+eb}).
//
// - fromPolynomial: the change of basis of a Cartesian polynomial by the multinomial
//   expansion of x = Σ λa Va.x (homogenised with 1 = Σ λa): one exact linear map;
// - evaluation by de Casteljau; degree elevation;
// - degree reduction by iterated Petersen (thesis (5.2)-(5.4), generalised to the
//   tetrahedron): one step n → n-1 computes, for each vertex a, the degree n-1 simplex that
//   inverts degree elevation starting from Va (it interpolates the corner), and assembles
//   them: each coefficient β takes the mean of the approximations of the vertices where β
//   has its largest component (for curves: the left half from the left solution, the right
//   half from the right one, the middle averaged). The restriction of the result to an edge
//   or face is the reduction of the restriction (boundary restriction ⇒ G0 between cells),
//   and reducing an elevated simplex returns it exactly;
// - reduceQuarticClosedForm: the thesis's closed formulas (5.5) for n = 4 → 2.
#pragma once
#include <array>
#include <vector>

#include <Eigen/Dense>

#include "modeling/modelers/bb_quadric.h"
#include "modeling/algebraic/polynomial3.h"

namespace qacc {

using MultiIndex4 = std::array<int, 4>;

class BBTetra {
 public:
  BBTetra() = default;
  BBTetra(int degree, const Tetrahedron& v);  // all coefficients zero

  int degree() const { return n_; }
  const Tetrahedron& vertices() const { return V_; }
  // All multi-indices of degree n in the fixed storage order.
  static const std::vector<MultiIndex4>& multiIndices(int n);
  static int index(int n, const MultiIndex4& a);
  static double multinomial(int n, const MultiIndex4& a);  // n! / (α0! α1! α2! α3!)

  double coefficient(const MultiIndex4& a) const { return c_[std::size_t(index(n_, a))]; }
  void setCoefficient(const MultiIndex4& a, double v) { c_[std::size_t(index(n_, a))] = v; }
  const std::vector<double>& coefficients() const { return c_; }

  // The polynomial f on the tetrahedron (exact change of basis up to rounding).
  static BBTetra fromPolynomial(const Polynomial3& f, const Tetrahedron& v);
  // The degree-2 form of a BB quadric (same coefficients).
  static BBTetra fromBBQuadric(const BBQuadric& q);
  // Degree-2 only: the BB quadric (coefficient matrix), for toQuadric / toPrimitive.
  BBQuadric toBBQuadric() const;

  Eigen::Vector4d barycentric(const Eigen::Vector3d& p) const;
  double evalBarycentric(const Eigen::Vector4d& lambda) const;  // de Casteljau
  double eval(const Eigen::Vector3d& p) const { return evalBarycentric(barycentric(p)); }

  // +1 if every coefficient is > 0, -1 if every one is < 0, 0 otherwise. By the convex
  // hull property ±1 means f has no zero in the closed tetrahedron.
  int strictSign() const;

  BBTetra elevated() const;                // degree n + 1, same polynomial
  BBTetra reducedOnce() const;             // iterated Petersen step n → n - 1 (n >= 1)
  BBTetra reducedTo(int degree) const;     // repeated steps

 private:
  int n_ = 0;
  Tetrahedron V_{};
  std::vector<double> c_;
};

// Thesis (5.5), applied on the 6 edges: vertex coefficients copied, edge coefficient
// A_{ea+eb} = -½B_{4ea} + B_{3ea+eb} - ½B_{4eb} + B_{ea+3eb}. Requires degree 4.
BBTetra reduceQuarticClosedForm(const BBTetra& quartic);

// Digest §4 general rule for degree n → 2 from values and gradients at the vertices:
// A_{2ea} = f(Va), A_{ea+eb} = ½[f(Va) + ½∇f(Va)·(Vb-Va) + f(Vb) + ½∇f(Vb)·(Va-Vb)].
BBTetra reduceByVertexRule(const Polynomial3& f, const Tetrahedron& v);

}  // namespace qacc
