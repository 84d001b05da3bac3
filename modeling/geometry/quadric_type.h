// Affine classification of a quadric into the 17 real and imaginary types plus the
// linear and constant cases.
//
// Method: the quadratic part E (3x3) is diagonalised by a rotation (eigenvalues λ, which
// are invariant under rigid motions); the linear part is rotated into the eigenbasis and
// every component along a non-zero λ is removed by completing the square (a translation),
// which leaves a constant J' and a linear part h in the null space of E. The type follows
// from the signs of λ, whether h is zero and the sign of J'.
//
// Tolerance policy (scale-invariant): with a relative tolerance τ (default 1e-9),
//  - λ_i counts as zero when |λ_i| <= τ · max|λ|;
//  - h counts as zero when |h| <= τ · |g| (g the original linear part);
//  - J' counts as zero when |J'| <= τ · (|J| + Σ g'_i² / |λ_i|), i.e. relative to the
//    magnitudes that were cancelled to form it.
// Every test compares quantities that scale alike, so the result is invariant under
// Q → kQ for any k ≠ 0 and under rigid motions (up to the rounding of the motion itself).
#pragma once
#include <string>

#include "modeling/geometry/quadric.h"

namespace qacc {

enum class QuadricType {
  // The 9 non-degenerate real types.
  Ellipsoid,
  HyperboloidOneSheet,
  HyperboloidTwoSheets,
  EllipticParaboloid,
  HyperbolicParaboloid,
  EllipticCone,
  EllipticCylinder,
  HyperbolicCylinder,
  ParabolicCylinder,
  // Degenerate real types.
  IntersectingPlanes,
  ParallelPlanes,
  CoincidentPlanes,
  Line,   // imaginary intersecting planes: a real line
  Point,  // imaginary cone: a real point
  Plane,  // linear f (E = 0): a single plane
  // Empty (imaginary) types.
  ImaginaryEllipsoid,
  ImaginaryEllipticCylinder,
  ImaginaryParallelPlanes,
  Empty,  // non-zero constant
  All,    // f ≡ 0
};

struct QuadricClass {
  QuadricType type = QuadricType::All;
  int positive = 0, negative = 0, zero = 3;  // signs of the eigenvalues of E (after sign normalisation)
  double constant = 0;                        // J' / max|λ| after completing the square
};

QuadricClass classifyQuadric(const Quadric& q, double tolerance = 1e-9);
inline QuadricType quadricType(const Quadric& q, double tolerance = 1e-9) {
  return classifyQuadric(q, tolerance).type;
}
const char* quadricTypeName(QuadricType t);
bool isNonDegenerate(QuadricType t);  // one of the 9 non-degenerate real types

}  // namespace qacc
