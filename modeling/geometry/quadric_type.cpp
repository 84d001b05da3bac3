#include "modeling/geometry/quadric_type.h"

#include <algorithm>
#include <cmath>

namespace qacc {

QuadricClass classifyQuadric(const Quadric& q, double tol) {
  const Matrix3d E = q.Q.topLeftCorner<3, 3>();
  const Vector3d g = q.Q.block<3, 1>(0, 3);
  const double J = q.Q(3, 3);
  QuadricClass out;

  Eigen::SelfAdjointEigenSolver<Matrix3d> es(E);
  Vector3d lam = es.eigenvalues();
  const Vector3d gp = es.eigenvectors().transpose() * g;
  const double lmax = lam.cwiseAbs().maxCoeff();

  int pos = 0, neg = 0;
  double hsq = 0, cancelled = std::abs(J), Jp = J;
  for (int i = 0; i < 3; ++i) {
    if (lmax > 0 && std::abs(lam[i]) > tol * lmax) {
      (lam[i] > 0 ? pos : neg)++;
      Jp -= gp[i] * gp[i] / lam[i];
      cancelled += gp[i] * gp[i] / std::abs(lam[i]);
    } else {
      hsq += gp[i] * gp[i];
    }
  }
  const bool hZero = std::sqrt(hsq) <= tol * g.norm();
  const bool jZero = std::abs(Jp) <= tol * cancelled;
  // Normalise the sign so that there are at least as many positive eigenvalues.
  if (neg > pos) {
    std::swap(pos, neg);
    Jp = -Jp;
  }
  out.positive = pos;
  out.negative = neg;
  out.zero = 3 - pos - neg;
  out.constant = lmax > 0 ? (jZero ? 0.0 : Jp / lmax) : Jp;
  const int rank = pos + neg;
  using T = QuadricType;

  if (rank == 3) {
    if (jZero) out.type = neg == 0 ? T::Point : T::EllipticCone;
    else if (neg == 0) out.type = Jp < 0 ? T::Ellipsoid : T::ImaginaryEllipsoid;
    else out.type = Jp < 0 ? T::HyperboloidOneSheet : T::HyperboloidTwoSheets;
  } else if (rank == 2) {
    if (!hZero) out.type = neg == 0 ? T::EllipticParaboloid : T::HyperbolicParaboloid;
    else if (neg == 0)
      out.type = jZero ? T::Line : (Jp < 0 ? T::EllipticCylinder : T::ImaginaryEllipticCylinder);
    else out.type = jZero ? T::IntersectingPlanes : T::HyperbolicCylinder;
  } else if (rank == 1) {
    if (!hZero) out.type = T::ParabolicCylinder;
    else out.type = jZero ? T::CoincidentPlanes : (Jp < 0 ? T::ParallelPlanes : T::ImaginaryParallelPlanes);
  } else {
    const bool linearZero = g.norm() == 0.0;
    if (!linearZero) out.type = T::Plane;
    else out.type = J == 0.0 ? T::All : T::Empty;
  }
  return out;
}

const char* quadricTypeName(QuadricType t) {
  switch (t) {
    case QuadricType::Ellipsoid: return "ellipsoid";
    case QuadricType::HyperboloidOneSheet: return "hyperboloid of one sheet";
    case QuadricType::HyperboloidTwoSheets: return "hyperboloid of two sheets";
    case QuadricType::EllipticParaboloid: return "elliptic paraboloid";
    case QuadricType::HyperbolicParaboloid: return "hyperbolic paraboloid";
    case QuadricType::EllipticCone: return "elliptic cone";
    case QuadricType::EllipticCylinder: return "elliptic cylinder";
    case QuadricType::HyperbolicCylinder: return "hyperbolic cylinder";
    case QuadricType::ParabolicCylinder: return "parabolic cylinder";
    case QuadricType::IntersectingPlanes: return "intersecting planes";
    case QuadricType::ParallelPlanes: return "parallel planes";
    case QuadricType::CoincidentPlanes: return "coincident planes";
    case QuadricType::Line: return "line";
    case QuadricType::Point: return "point";
    case QuadricType::Plane: return "plane";
    case QuadricType::ImaginaryEllipsoid: return "imaginary ellipsoid";
    case QuadricType::ImaginaryEllipticCylinder: return "imaginary elliptic cylinder";
    case QuadricType::ImaginaryParallelPlanes: return "imaginary parallel planes";
    case QuadricType::Empty: return "empty";
    case QuadricType::All: return "all space";
  }
  return "?";
}

bool isNonDegenerate(QuadricType t) {
  return static_cast<int>(t) <= static_cast<int>(QuadricType::ParabolicCylinder);
}

}  // namespace qacc
