#include "modeling/geometry/quadric.h"

namespace qacc {

Quadric::Quadric(const Matrix4d& m) : Q(0.5 * (m + m.transpose())) {}

Quadric Quadric::fromCoefficients(double A, double B, double C, double D, double E, double F,
                                  double G, double H, double I, double J) {
  Matrix4d m;
  m << A, D, F, G,
       D, B, E, H,
       F, E, C, I,
       G, H, I, J;
  return Quadric(m);
}

Quadric Quadric::fromPlainCoefficients(double A, double B, double C, double D, double E,
                                       double F, double G, double H, double I, double J) {
  return fromCoefficients(A, B, C, D / 2, E / 2, F / 2, G / 2, H / 2, I / 2, J);
}

Quadric Quadric::transformed(const Matrix4d& M) const {
  return transformedByInverse(M.inverse());
}

Quadric Quadric::transformedByInverse(const Matrix4d& Minv) const {
  return Quadric(Matrix4d(Minv.transpose() * Q * Minv));
}

Quadric Quadric::normalized() const {
  const double m = maxAbsCoefficient();
  if (m == 0.0) return *this;
  return Quadric(Matrix4d(Q / m));
}

}  // namespace qacc
