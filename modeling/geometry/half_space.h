// Half-space p = (a, b, c, d): keeps the points with a x + b y + c z + d <= 0.
//
// Boundary ownership (design §2, "a point exactly on a clip plane belongs to exactly one
// side"): a point with p·X == 0 is kept only by the orientation of the plane whose first
// non-zero coefficient (in a, b, c, d order, in world space) is negative. The opposite
// half-space -p of a neighbouring cell therefore keeps exactly the points this one drops,
// including the plane itself, so two cells sharing a plane never both drop a pixel and
// never both keep a point of the plane. `owns_boundary` is fixed at construction in world
// space and travels unchanged through transforms (a transform changes the coefficients,
// not which side owns the plane).
#pragma once
#include <Eigen/Dense>

namespace qacc {

struct HalfSpace {
  Eigen::Vector4d p = Eigen::Vector4d::Zero();
  bool owns_boundary = false;

  HalfSpace() = default;
  explicit HalfSpace(const Eigen::Vector4d& plane) : p(plane), owns_boundary(firstNonZeroNegative(plane)) {}
  HalfSpace(const Eigen::Vector4d& plane, bool owns) : p(plane), owns_boundary(owns) {}

  // Plane through `point` with outward normal `n` (kept side is opposite to n).
  static HalfSpace fromPointNormal(const Eigen::Vector3d& point, const Eigen::Vector3d& n) {
    return HalfSpace(Eigen::Vector4d(n.x(), n.y(), n.z(), -n.dot(point)));
  }

  double evalHomogeneous(const Eigen::Vector4d& X) const { return p.dot(X); }
  double eval(const Eigen::Vector3d& x) const { return p.dot(x.homogeneous()); }
  // The kept side for a signed value v = p·X, with the ownership rule on v == 0.
  bool keeps(double v) const { return v < 0.0 || (v == 0.0 && owns_boundary); }
  bool contains(const Eigen::Vector3d& x) const { return keeps(eval(x)); }

  // The opposite half-space: keeps exactly what this one drops.
  HalfSpace opposite() const { return HalfSpace(Eigen::Vector4d(-p), !owns_boundary); }

  // After points move as X' = M X: p' = M⁻ᵀ p (given M⁻¹).
  HalfSpace transformedByInverse(const Eigen::Matrix4d& Minv) const {
    return HalfSpace(Eigen::Vector4d(Minv.transpose() * p), owns_boundary);
  }

  static bool firstNonZeroNegative(const Eigen::Vector4d& v) {
    for (int i = 0; i < 4; ++i)
      if (v[i] != 0.0) return v[i] < 0.0;
    return false;
  }
};

}  // namespace qacc
