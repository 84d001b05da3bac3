// Quadric surface f(X) = Xᵀ Q X with X = (x, y, z, 1)ᵀ and Q symmetric 4x4.
// Coefficient names follow thesis (3.1):
//   A x² + B y² + C z² + 2D xy + 2E yz + 2F zx + 2G x + 2H y + 2I z + J = 0,
//   Q = [[A,D,F,G],[D,B,E,H],[F,E,C,I],[G,H,I,J]].
// The solid interior is f <= 0; the constructors of natural quadrics orient them so.
#pragma once
#include <Eigen/Dense>

namespace qacc {

using Eigen::Matrix3d;
using Eigen::Matrix4d;
using Eigen::Vector3d;
using Eigen::Vector4d;

struct Quadric {
  Matrix4d Q = Matrix4d::Zero();

  Quadric() = default;
  // Symmetrises the given matrix ((M + Mᵀ) / 2).
  explicit Quadric(const Matrix4d& m);

  // Thesis (3.1) coefficients (factors of 2 on the cross and linear terms).
  static Quadric fromCoefficients(double A, double B, double C, double D, double E, double F,
                                  double G, double H, double I, double J);
  // Thesis (1.11) coefficients, no factors of 2:
  //   A x² + B y² + C z² + D xy + E yz + F xz + G x + H y + I z + J = 0.
  static Quadric fromPlainCoefficients(double A, double B, double C, double D, double E,
                                       double F, double G, double H, double I, double J);

  double eval(const Vector3d& p) const { return evalHomogeneous(p.homogeneous()); }
  double evalHomogeneous(const Vector4d& X) const { return X.dot(Q * X); }
  // ∇f = 2 (Q X)_xyz.
  Vector3d gradient(const Vector3d& p) const {
    return 2.0 * (Q * p.homogeneous()).head<3>();
  }

  // The same surface after points move as X' = M X (any invertible 4x4, perspective
  // included): Q' = M⁻ᵀ Q M⁻¹.
  Quadric transformed(const Matrix4d& M) const;
  // Q' = Mᵢᵀ Q Mᵢ given the inverse map Mᵢ = M⁻¹ directly.
  Quadric transformedByInverse(const Matrix4d& Minv) const;

  // Q scaled so that its largest coefficient magnitude is 1 (same surface, same sign).
  Quadric normalized() const;
  // Same surface with the interior and exterior swapped.
  Quadric flipped() const { return Quadric(Matrix4d(-Q)); }

  double maxAbsCoefficient() const { return Q.cwiseAbs().maxCoeff(); }
};

}  // namespace qacc
