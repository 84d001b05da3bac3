#include "modeling/geometry/primitive_bounds.h"

#include <cmath>
#include <limits>

#include "modeling/geometry/quadric_type.h"

namespace qacc {
namespace {

constexpr double kFar = 1e12;  // a box this large stands for "unbounded"

// Extent of the clip polyhedron ∩ [−kFar, kFar]³ by vertex enumeration.
bool polytopeExtent(const std::vector<HalfSpace>& clip, Eigen::AlignedBox3d& box) {
  std::vector<Eigen::Vector4d> P;
  for (const auto& h : clip) P.push_back(h.p);
  for (int a = 0; a < 3; ++a)
    for (double s : {-1.0, 1.0}) {
      Eigen::Vector4d p = Eigen::Vector4d::Zero();
      p[a] = s;
      p[3] = -kFar;
      P.push_back(p);
    }
  box.setEmpty();
  const std::size_t n = P.size();
  for (std::size_t i = 0; i < n; ++i)
    for (std::size_t j = i + 1; j < n; ++j)
      for (std::size_t k = j + 1; k < n; ++k) {
        Eigen::Matrix3d A;
        A << P[i].head<3>().transpose(), P[j].head<3>().transpose(), P[k].head<3>().transpose();
        const double scale = P[i].head<3>().norm() * P[j].head<3>().norm() * P[k].head<3>().norm();
        if (!(std::abs(A.determinant()) > 1e-12 * scale)) continue;
        const Eigen::Vector3d v = A.inverse() * Eigen::Vector3d(-P[i][3], -P[j][3], -P[k][3]);
        bool ok = v.allFinite();
        for (std::size_t m = 0; ok && m < n; ++m) {
          const double mag = P[m].head<3>().cwiseAbs().dot(v.cwiseAbs()) + std::abs(P[m][3]);
          if (P[m].dot(v.homogeneous()) > 1e-9 * mag) ok = false;
        }
        if (!ok) continue;
        box.extend(v);
      }
  return !box.isEmpty();
}

}  // namespace

PrimitiveBounds primitiveBounds(const Primitive& prim) {
  PrimitiveBounds out;
  Eigen::AlignedBox3d poly;
  if (!polytopeExtent(prim.clip, poly)) {
    out.empty = true;
    return out;
  }
  Eigen::AlignedBox3d surf(Eigen::Vector3d::Constant(-kFar), Eigen::Vector3d::Constant(kFar));
  if (quadricType(prim.quadric) == QuadricType::Ellipsoid) {  // surface and solid alike
    const Eigen::Matrix4d D = prim.quadric.Q.inverse();  // dual quadric
    for (int a = 0; a < 3; ++a) {
      // (e_a − t e_4)ᵀ D (e_a − t e_4) = D_aa − 2 t D_a4 + t² D_44 = 0
      const double A = D(3, 3), B = -D(a, 3), C = D(a, a);
      const double disc = B * B - A * C;
      if (A == 0 || disc < 0) continue;
      const double s = std::sqrt(disc);
      const double t1 = (-B - s) / A, t2 = (-B + s) / A;
      surf.min()[a] = std::min(t1, t2);
      surf.max()[a] = std::max(t1, t2);
    }
  }
  out.box = poly.intersection(surf);
  if (out.box.isEmpty()) {
    out.empty = true;
    return out;
  }
  out.bounded = out.box.min().cwiseAbs().maxCoeff() < 0.5 * kFar && out.box.max().cwiseAbs().maxCoeff() < 0.5 * kFar;
  return out;
}

}  // namespace qacc
