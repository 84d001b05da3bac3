#include "modeling/tessellation/quadric_frame.h"

#include <cmath>
#include <utility>

namespace qacc::tess {

Frame canonicalFrame(const Quadric& q) {
  Frame f;
  Matrix4d Q = q.normalized().Q;
  Eigen::SelfAdjointEigenSolver<Matrix3d> es(Q.topLeftCorner<3, 3>());
  int pos = 0, neg = 0;
  const double tol = 1e-9 * es.eigenvalues().cwiseAbs().maxCoeff();
  for (int i = 0; i < 3; ++i) {
    if (es.eigenvalues()[i] > tol) ++pos;
    if (es.eigenvalues()[i] < -tol) ++neg;
  }
  if (neg > pos) Q = -Q;
  f.E = Q.topLeftCorner<3, 3>();
  f.g = Q.topRightCorner<3, 1>();
  f.J = Q(3, 3);
  Eigen::SelfAdjointEigenSolver<Matrix3d> es2(f.E);
  f.lambda = es2.eigenvalues();
  f.V = es2.eigenvectors();
  return f;
}

// Reorder the frame's columns so that column 2 is the eigenvector `axis`.
void putAxisLast(Frame& f, int axis) {
  if (axis == 2) return;
  std::swap(f.lambda[axis], f.lambda[2]);
  f.V.col(axis).swap(f.V.col(2));
}

// Centre in the span of the non-zero eigenvalues: c = −Σ (vᵢ·g / λᵢ) vᵢ.
Vector3d partialCentre(const Frame& f, double tol) {
  Vector3d c = Vector3d::Zero();
  for (int i = 0; i < 3; ++i)
    if (std::abs(f.lambda[i]) > tol) c -= (f.V.col(i).dot(f.g) / f.lambda[i]) * f.V.col(i);
  return c;
}

double evalFrame(const Frame& f, const Vector3d& x) { return x.dot(f.E * x) + 2 * f.g.dot(x) + f.J; }

Frame axialFrame(const Quadric& q, QuadricType type, double* tol) {
  Frame f = canonicalFrame(q);
  const double ltol = 1e-9 * f.lambda.cwiseAbs().maxCoeff();
  auto indexOfSign = [&](int sign) {  // index of the eigenvalue with this sign (0 = zero)
    for (int i = 0; i < 3; ++i) {
      const int s = f.lambda[i] > ltol ? 1 : (f.lambda[i] < -ltol ? -1 : 0);
      if (s == sign) return i;
    }
    return -1;
  };
  switch (type) {  // the axis of the axial types is the last column of the frame
    case QuadricType::EllipticCylinder:
    case QuadricType::EllipticParaboloid: putAxisLast(f, indexOfSign(0)); break;
    case QuadricType::EllipticCone:
    case QuadricType::HyperboloidOneSheet:
    case QuadricType::HyperboloidTwoSheets: putAxisLast(f, indexOfSign(-1)); break;
    default: break;
  }
  *tol = ltol;
  return f;
}

}  // namespace qacc::tess
