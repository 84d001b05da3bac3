#include "modeling/geometry/piece_extent.h"

#include <cmath>
#include <limits>

#include "modeling/geometry/partial_pivot_solve3.h"
#include "modeling/geometry/stable_roots.h"

namespace qacc {

bool insidePolytope(const std::vector<Eigen::Vector4d>& P, const Eigen::Vector3d& v) {
  const Eigen::Vector4d X = v.homogeneous();
  for (const auto& p : P) {
    // The tolerance is never negative: a point on the inner side needs no magnitude.
    const double side = p.dot(X);
    if (!(side > 0)) continue;
    const double mag = std::abs(p[0] * X[0]) + std::abs(p[1] * X[1]) + std::abs(p[2] * X[2]) + std::abs(p[3]);
    if (side > 1e-9 * mag) return false;
  }
  return true;
}

std::vector<Eigen::Vector3d> polytopeVertices(const std::vector<Eigen::Vector4d>& P, const Eigen::Vector4d* plane) {
  std::vector<Eigen::Vector3d> out;
  auto consider = [&](const Eigen::Vector4d& p, const Eigen::Vector4d& q, const Eigen::Vector4d& r) {
    Eigen::Matrix3d A;
    A << p.head<3>().transpose(), q.head<3>().transpose(), r.head<3>().transpose();
    const double scale = p.head<3>().norm() * q.head<3>().norm() * r.head<3>().norm();
    if (!(std::abs(A.determinant()) > 1e-12 * scale)) return;
    const Eigen::Vector3d v = A.inverse() * Eigen::Vector3d(-p[3], -q[3], -r[3]);
    if (v.allFinite() && insidePolytope(P, v)) out.push_back(v);
  };
  const std::size_t n = P.size();
  for (std::size_t i = 0; i < n; ++i)
    for (std::size_t j = i + 1; j < n; ++j) {
      if (plane) {
        consider(*plane, P[i], P[j]);
        continue;
      }
      for (std::size_t k = j + 1; k < n; ++k) consider(P[i], P[j], P[k]);
    }
  return out;
}

namespace {

// |H|ᵀ |Q| |H|: the magnitude of the terms that cancel in f(H) = Hᵀ Q H, the scale a
// tolerance on f(H) is relative to (not |Q| |H|², which is far too large for a point far
// from the origin along a direction the quadric is only linear in).
double cancelled(const Eigen::Matrix4d& Q, const Eigen::Vector4d& H) {
  const Eigen::Vector4d Ha = H.cwiseAbs();
  return Ha.dot(Q.cwiseAbs() * Ha);
}

// Points of the line {a·X = 0, b·X = 0} on the quadric and inside P; a line lying on the
// quadric contributes its ends in P. Qa = |Q| (element-wise), computed once per piece.
void lineCandidates(const Eigen::Matrix4d& Q, const Eigen::Matrix4d& Qa, const Eigen::Vector4d& a,
                    const Eigen::Vector4d& b, const std::vector<Eigen::Vector4d>& P, const Eigen::Vector3d& ref,
                    Eigen::AlignedBox3d& ext) {
  const Eigen::Vector3d na = a.head<3>(), nb = b.head<3>();
  const Eigen::Vector3d d = na.cross(nb);
  if (!(d.norm() > 1e-12 * na.norm() * nb.norm())) return;
  Eigen::Matrix3d A;
  A << na.transpose(), nb.transpose(), d.transpose();
  const Eigen::Vector3d X0 = partialPivotSolve3(A, Eigen::Vector3d(-a[3], -b[3], d.dot(ref)));  // = partialPivLu().solve
  if (!X0.allFinite()) return;
  const Eigen::Vector4d H0 = X0.homogeneous(), D(d.x(), d.y(), d.z(), 0);
  const double qa = D.dot(Q * D), qb = D.dot(Q * H0), qc = H0.dot(Q * H0);
  // Each coefficient against the magnitudes that cancelled to form it (|u|ᵀ|Q||v|), so that
  // a line far from the origin is not taken for a line on the quadric because the
  // quadric's terms in the large coordinates happen to be absent.
  const Eigen::Vector4d Da = D.cwiseAbs(), Ha = H0.cwiseAbs();
  if (std::abs(qa) <= 1e-13 * Da.dot(Qa * Da) && std::abs(qb) <= 1e-13 * Da.dot(Qa * Ha) &&
      std::abs(qc) <= 1e-13 * Ha.dot(Qa * Ha)) {
    // The whole line is on the quadric: its ends inside P.
    double lo = -std::numeric_limits<double>::infinity(), hi = -lo;
    for (const auto& p : P) {
      const double al = p.dot(D), be = p.dot(H0);
      if (al > 0) hi = std::min(hi, -be / al);
      else if (al < 0) lo = std::max(lo, -be / al);
      else if (be > 0) return;
    }
    if (lo <= hi && std::isfinite(lo) && std::isfinite(hi)) {
      ext.extend(Eigen::Vector3d(X0 + lo * d));
      ext.extend(Eigen::Vector3d(X0 + hi * d));
    }
    return;
  }
  const QuadraticRoots r = stableRoots(qa, qb, qc);
  for (int i = 0; i < r.count; ++i) {
    const Eigen::Vector3d v = X0 + r.r[i] * d;
    if (v.allFinite() && insidePolytope(P, v)) ext.extend(v);
  }
}

// addAxisCandidates with Qa = |Q| given (pieceExtent computes it once for all its lines).
void axisCandidates(const Eigen::Matrix4d& Q, const Eigen::Matrix4d& Qa, const std::vector<Eigen::Vector4d>& P,
                    const Eigen::Vector3d& ref, int ax, Eigen::AlignedBox3d& ext, UnreachablePlanes unreachable) {
  const Eigen::Matrix<double, 3, 4> G = Q.topRows<3>();  // ∇f / 2 = G X
  // (a) ∇f parallel to the axis: the two other gradient components vanish.
  const int o1 = ax == 0 ? 1 : 0, o2 = ax == 2 ? 1 : 2;
  lineCandidates(Q, Qa, G.row(o1).transpose(), G.row(o2).transpose(), P, ref, ext);
  // (b) on each face: ∇f · (n × axis) = 0.
  const Eigen::Vector3d axis = Eigen::Vector3d::Unit(ax);
  for (std::size_t i = 0; i < P.size(); ++i) {
    if (unreachable.has(i)) continue;
    const Eigen::Vector4d& p = P[i];
    const Eigen::Vector3d m = p.head<3>().cross(axis);
    if (m.norm() <= 1e-12 * p.head<3>().norm()) continue;  // face ⟂ axis: its edges bound it
    lineCandidates(Q, Qa, p, (m.transpose() * G).transpose(), P, ref, ext);
  }
}

}  // namespace

void addAxisCandidates(const Eigen::Matrix4d& Q, const std::vector<Eigen::Vector4d>& P, const Eigen::Vector3d& ref,
                       int ax, Eigen::AlignedBox3d& ext, UnreachablePlanes unreachable) {
  axisCandidates(Q, Q.cwiseAbs(), P, ref, ax, ext, unreachable);
}

Eigen::AlignedBox3d pieceExtent(const Eigen::Matrix4d& Q, const std::vector<Eigen::Vector4d>& P, bool solid,
                                const Eigen::Vector3d& ref, int axes, UnreachablePlanes unreachable) {
  Eigen::AlignedBox3d ext;  // empty
  const Eigen::Matrix4d Qa = Q.cwiseAbs();
  for (int ax = 0; ax < axes; ++ax) axisCandidates(Q, Qa, P, ref, ax, ext, unreachable);
  // (c) each edge of the polytope against the surface.
  for (std::size_t i = 0; i < P.size(); ++i) {
    if (unreachable.has(i)) continue;
    for (std::size_t j = i + 1; j < P.size(); ++j)
      if (!unreachable.has(j)) lineCandidates(Q, Qa, P[i], P[j], P, ref, ext);
  }
  // The singular point of a cone.
  const Eigen::Matrix3d E = Q.topLeftCorner<3, 3>();
  Eigen::FullPivLU<Eigen::Matrix3d> lu(E);
  if (lu.isInvertible()) {
    const Eigen::Vector3d apex = lu.solve(Eigen::Vector3d(-Q.block<3, 1>(0, 3)));
    const Eigen::Vector4d H = apex.homogeneous();
    if (apex.allFinite() && std::abs(H.dot(Q * H)) <= 1e-9 * cancelled(Q, H) && insidePolytope(P, apex))
      ext.extend(apex);
  }
  // Solids: corners of the caps.
  if (solid) {
    for (const auto& v : polytopeVertices(P, nullptr)) {
      const Eigen::Vector4d H = v.homogeneous();
      if (H.dot(Q * H) <= 1e-9 * cancelled(Q, H)) ext.extend(v);
    }
  }
  return ext;
}

}  // namespace qacc
