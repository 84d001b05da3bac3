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

// The curve from a traced until one of `targets` is within a step: steps along the tangent
// (the way that enters the face), each as long as the curvature allows within the
// tolerance, moved back onto the curve; `span` sets the probe and the shortest and longest
// steps.
// `reached`: the index in `targets` of the point the trace ended on.
std::optional<std::vector<Vector3d>> traceSharedCurve(const Quadric& q, const HalfSpace& h,
                                                      const std::vector<HalfSpace>& face, const Vector3d& a,
                                                      const std::vector<Vector3d>& targets, double span,
                                                      const PolylineTolerance& tol, std::size_t* reached = nullptr) {
  Domain curve;
  curve.surface = &q;
  const Vector3d n = h.p.head<3>().normalized();
  const Eigen::Matrix3d H = 2.0 * q.Q.topLeftCorner<3, 3>();
  if (!(span > 0) || targets.empty()) return std::nullopt;
  auto tangent = [&](const Vector3d& x) {
    const Vector3d g = q.gradient(x);
    return Vector3d((g - g.dot(n) * n).cross(n));
  };
  auto onCurve = [&](const Vector3d& x) {
    const Vector3d g = q.gradient(x);
    return g.norm() > 0 && std::abs(q.eval(x)) <= 1e-9 * g.norm() * (1 + x.norm());
  };
  Vector3d t = tangent(a);
  if (!(t.norm() > 0)) return std::nullopt;
  t.normalize();
  // The way into the face: probed at 1e-3 of the span, or a quarter of the way to the nearest
  // target when that is nearer (an arc shorter than the probe, at a corner of the face).
  double probe = 1e-3 * span;
  for (const Vector3d& y : targets)
    if ((y - a).norm() > 0) probe = std::min(probe, std::max(0.25 * (y - a).norm(), 1e-6 * (1 + a.norm())));
  const Vector3d fwd = curve.ontoCurve(a + probe * t, h, span), bwd = curve.ontoCurve(a - probe * t, h, span);
  const bool inF = onCurve(fwd) && insideFace(face, fwd, 1e-9), inB = onCurve(bwd) && insideFace(face, bwd, 1e-9);
  if (inF == inB) return std::nullopt;
  if (inB) t = -t;
  std::vector<Vector3d> out{a};
  Vector3d x = a;
  constexpr int kMaxSteps = 1 << 12;
  for (int step = 0; step < kMaxSteps; ++step) {
    Vector3d tx = tangent(x);
    if (!(tx.norm() > 0)) return std::nullopt;
    tx.normalize();
    if (tx.dot(t) < 0) tx = -tx;
    t = tx;
    const Vector3d g = q.gradient(x);
    const double gp = (g - g.dot(n) * n).norm();
    const double kappa = std::abs(t.dot(H * t)) / gp;
    double world = tol.world;
    if (tol.view && tol.pixels > 0) {
      const double w = tol.pixels / tol.view->pixelsPerUnit(x);
      world = world > 0 ? std::min(world, w) : w;
    }
    if (!(world > 0)) world = 1e-3 * span;
    double len = kappa > 0 ? std::sqrt(8 * world / kappa) : span;
    len = std::clamp(len, 1e-4 * span, 0.25 * span);
    for (std::size_t k = 0; k < targets.size(); ++k)
      if ((targets[k] - x).norm() <= len && (step > 0 || (targets[k] - a).dot(t) > 0)) {
        out.push_back(targets[k]);
        if (reached) *reached = k;
        return out;
      }
    const Vector3d y = curve.ontoCurve(x + len * t, h, 2 * len);
    if (!onCurve(y) || !insideFace(face, y, 1e-6) || !((y - x).norm() > 0)) return std::nullopt;
    out.push_back(y);
    x = y;
  }
  return std::nullopt;
}

}  // namespace

std::vector<Vector3d> sharedCurveEnds(const Quadric& q, const HalfSpace& h, const std::vector<HalfSpace>& face) {
  const Vector3d nh = h.p.head<3>().normalized();
  // Two planes of the face that cut h along one line from opposite sides (their traces on h
  // opposite: the same plane, reversed, or two planes through one line of h, as where cells'
  // tetrahedra meet at an edge on a shared plane): the pieces meet along a line at most,
  // sharing no arc. A plane's trace on h is its coefficients less their component along h's.
  std::vector<Eigen::Vector4d> trace;
  for (const HalfSpace& g : face) {
    const Eigen::Vector4d t = g.p - (g.p.dot(h.p) / h.p.squaredNorm()) * h.p;
    trace.push_back(t.norm() > 1e-12 * g.p.norm() ? Eigen::Vector4d(t.normalized()) : Eigen::Vector4d::Zero());
  }
  for (std::size_t i = 0; i < face.size(); ++i)
    for (std::size_t j = i + 1; j < face.size(); ++j)
      if (trace[i].norm() > 0 && trace[j].norm() > 0 && (trace[i] + trace[j]).norm() <= 1e-9) return {};
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
  if (ends.size() <= 1) return {};  // the faces meet at a point at most
  if (ends.size() == 2) return ends;
  // More: each end not yet in an arc traced into the face to the end it reaches (an end
  // where the curve only passes through a corner of the face has no way in and is no end).
  double span = 0;
  for (const Vector3d& x : ends)
    for (const Vector3d& y : ends) span = std::max(span, (x - y).norm());
  PolylineTolerance coarse;
  coarse.world = 1e-3 * span;
  std::vector<Vector3d> arcs;
  std::vector<char> used(ends.size(), 0);
  for (std::size_t i = 0; i < ends.size(); ++i) {
    if (used[i]) continue;
    std::vector<Vector3d> targets;
    std::vector<std::size_t> index;
    for (std::size_t j = 0; j < ends.size(); ++j)
      if (j != i && !used[j]) {
        targets.push_back(ends[j]);
        index.push_back(j);
      }
    std::size_t reached = 0;
    if (!traceSharedCurve(q, h, face, ends[i], targets, span, coarse, &reached)) continue;
    used[i] = used[index[reached]] = 1;
    arcs.push_back(ends[i]);
    arcs.push_back(ends[index[reached]]);
  }
  return arcs;
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
  if (ok) {
    out.push_back(b);
    return out;
  }
  return traceSharedCurve(q, h, face, a, {b}, (b - a).norm(), tol);
}

}  // namespace qacc::tess
