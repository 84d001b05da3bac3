// The one polyline of a shared boundary (shared_polyline.h).
#include "modeling/tessellation/shared_polyline.h"

#include <algorithm>
#include <cmath>

#include "modeling/tessellation/surface_clipping.h"  // Domain::ontoCurve

namespace qacc::tess {

using Eigen::Vector3d;

namespace {

// x inside g, within rounding relative to the sizes of x (at least a unit: a point at the
// origin on a plane through it) and of g's coefficients.
bool insideWithin(const HalfSpace& g, const Vector3d& x, double rel) {
  return g.eval(x) <= rel * (g.p.head<3>().norm() * std::max(1.0, x.norm()) + std::abs(g.p[3]));
}

bool insideFace(const std::vector<HalfSpace>& face, const Vector3d& x, double rel, const HalfSpace* skip = nullptr) {
  for (const HalfSpace& g : face)
    if (&g != skip && !insideWithin(g, x, rel)) return false;
  return true;
}

// The roots of q along the line where h and g meet.
std::vector<Vector3d> lineRoots(const Quadric& q, const HalfSpace& h, const HalfSpace& g) {
  const Vector3d n1 = h.p.head<3>(), n2 = g.p.head<3>();
  const Vector3d d = n1.cross(n2);
  const double dd = d.squaredNorm();
  if (!(dd > 1e-24 * n1.squaredNorm() * n2.squaredNorm())) return {};
  const Vector3d p0 = ((-h.p[3]) * n2.cross(d) + (-g.p[3]) * d.cross(n1)) / dd;
  const Vector3d e = d / std::sqrt(dd);
  const double a = e.dot(q.Q.topLeftCorner<3, 3>() * e), b = q.gradient(p0).dot(e), c = q.eval(p0);
  std::vector<Vector3d> out;
  if (std::abs(a) <= 1e-14 * (std::abs(b) + std::abs(c) + 1e-300)) {
    if (std::abs(b) > 0) out.push_back(p0 + (-c / b) * e);
    return out;
  }
  const double disc = b * b - 4 * a * c;
  if (disc < 0) return out;
  const double qq = -0.5 * (b + std::copysign(std::sqrt(disc), b));
  out.push_back(p0 + (qq / a) * e);
  if (qq != 0 && disc > 0) out.push_back(p0 + (c / qq) * e);
  return out;
}

}  // namespace

std::optional<std::vector<Vector3d>> sharedCurveEnds(const Quadric& q, const HalfSpace& h,
                                                     const std::vector<HalfSpace>& face) {
  const Vector3d nh = h.p.head<3>().normalized();
  std::vector<Vector3d> ends;
  for (const HalfSpace& g : face)
    for (const Vector3d& x : lineRoots(q, h, g)) {
      if (!x.allFinite() || !insideFace(face, x, 1e-8, &g)) continue;
      // Where the curve leaves the face: it crosses a plane of the face there, not only
      // touches it (a G1 cell's surface is tangent to faces of its tetrahedron).
      const Vector3d grad = q.gradient(x);
      const Vector3d t = grad.cross(nh);
      if (!(t.norm() > 0)) continue;
      bool crosses = false;
      for (const HalfSpace& f : face)
        crosses = crosses || (insideWithin(f, x, 1e-8) && !insideWithin(f, x, -1e-8) &&
                              std::abs(t.dot(f.p.head<3>())) > 1e-6 * t.norm() * f.p.head<3>().norm());
      if (!crosses) continue;
      // A corner of the face lies on two of its planes: found once.
      bool known = false;
      for (const Vector3d& y : ends) known = known || (x - y).norm() <= 1e-7 * (1 + x.norm());
      if (!known) ends.push_back(x);
    }
  if (ends.size() <= 1) return std::vector<Vector3d>();  // the faces meet at a point at most
  if (ends.size() == 2) return ends;
  // More: the one pair of ends whose arc's middle lies inside the face (a point where the
  // curve only passes through a corner of the face is the end of no arc).
  Domain curve;
  curve.surface = &q;
  std::vector<Vector3d> arc;
  for (std::size_t i = 0; i < ends.size(); ++i)
    for (std::size_t j = i + 1; j < ends.size(); ++j) {
      const Vector3d m = curve.ontoCurve(0.5 * (ends[i] + ends[j]), h, (ends[j] - ends[i]).norm());
      if (std::abs(q.eval(m)) > 1e-9 * q.gradient(m).norm() * (1 + m.norm()) || !insideFace(face, m, 1e-9)) continue;
      if (!arc.empty()) return std::nullopt;
      arc = {ends[i], ends[j]};
    }
  return arc;
}

std::optional<std::vector<Vector3d>> sampleSharedCurve(const Quadric& q, const HalfSpace& h,
                                                       const std::vector<HalfSpace>& face, const Vector3d& a,
                                                       const Vector3d& b, const PolylineTolerance& tol) {
  Domain curve;
  curve.surface = &q;
  std::vector<Vector3d> out{a};
  bool ok = true;
  // Depth first, left half first: the points come out in order from a to b.
  auto split = [&](auto&& self, const Vector3d& p, const Vector3d& r, int depth) -> void {
    if (!ok) return;
    const Vector3d m = 0.5 * (p + r);
    const double chord = (r - p).norm();
    const Vector3d x = curve.ontoCurve(m, h, chord);
    const Vector3d g = q.gradient(x);
    if (!(g.norm() > 0) || std::abs(q.eval(x)) > 1e-9 * g.norm() * (1 + x.norm()) || !insideFace(face, x, 1e-6)) {
      ok = false;
      return;
    }
    const double sag = (x - m).norm();
    const bool fine = (tol.world <= 0 || sag <= tol.world) &&
                      (!tol.view || tol.pixels <= 0 || sag * tol.view->pixelsPerUnit(x) <= tol.pixels);
    if (fine || depth >= kMaxSharedPolylineDepth) return;
    self(self, p, x, depth + 1);
    out.push_back(x);
    self(self, x, r, depth + 1);
  };
  split(split, a, b, 0);
  if (!ok) return std::nullopt;
  out.push_back(b);
  return out;
}

}  // namespace qacc::tess
