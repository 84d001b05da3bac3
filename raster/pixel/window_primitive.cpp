#include "raster/pixel/window_primitive.h"

#include <cmath>
#include <limits>

#include "raster/pixel/stable_roots.h"

namespace qacc {
namespace {

ScreenBox screen(int w, int h) { return {0, 0, w, h}; }

// Pixel index range whose centres (i + 0.5) can lie in [lo, hi], widened by one pixel.
void pixelRange(double lo, double hi, int n, int& i0, int& i1) {
  const double a = std::ceil(lo - 0.5) - 1.0;
  const double b = std::floor(hi - 0.5) + 2.0;  // exclusive
  i0 = int(std::max(0.0, std::min(double(n), a)));
  i1 = int(std::max(0.0, std::min(double(n), b)));
}

// Extent in u of {(u, v): P u² + 2 R u v + S v² + 2 T u + 2 U v + K >= 0}; false = unbounded.
// Returns an empty range (lo > hi) when the region is empty.
bool axisExtent(double P, double R, double S, double T, double U, double K, double& lo, double& hi) {
  // Near-degenerate conics (parabolas, line pairs) are treated as unbounded: a rounding
  // error in the sign of S or of al must never make the box too small.
  constexpr double tol = 1e-9;
  if (!(S < -tol * (std::abs(P) + std::abs(R)))) return false;  // unbounded in v for some u
  // max over v is >= 0  <=>  (R² − P S) u² + 2 (R U − S T) u + (U² − S K) >= 0   (times −S > 0)
  const double al = R * R - P * S, be = R * U - S * T, ga = U * U - S * K;
  if (!(al < -tol * (R * R + std::abs(P * S)))) return false;
  // Stable roots: near a parabola al -> 0 and the naive formula loses the vertex root.
  const QuadraticRoots r = stableRoots(al, be, ga);
  if (r.count == 0) {
    lo = 1;
    hi = 0;
    return true;
  }
  lo = r.r[0];
  hi = r.r[r.count - 1];
  return std::isfinite(lo) && std::isfinite(hi);
}

Eigen::Vector4d normalisedPlane(const Eigen::Vector4d& p) {
  const double m = p.cwiseAbs().maxCoeff();
  return m > 0 ? Eigen::Vector4d(p / m) : p;
}

}  // namespace

Conic WindowPrimitive::contour() const {
  const double a = Q(2, 2), bx = Q(0, 2), by = Q(1, 2), b0 = Q(2, 3);
  Conic d;
  d.A = bx * bx - a * Q(0, 0);
  d.B = bx * by - a * Q(0, 1);
  d.C = by * by - a * Q(1, 1);
  d.D = bx * b0 - a * Q(0, 3);
  d.E = by * b0 - a * Q(1, 3);
  d.F = b0 * b0 - a * Q(3, 3);
  return d;
}

ScreenBox conicBox(const Conic& d, int width, int height) {
  ScreenBox box = screen(width, height);
  double lo, hi;
  if (axisExtent(d.A, d.B, d.C, d.D, d.E, d.F, lo, hi)) {
    if (lo > hi) return {};
    pixelRange(lo, hi, width, box.x0, box.x1);
  }
  if (axisExtent(d.C, d.B, d.A, d.E, d.D, d.F, lo, hi)) {
    if (lo > hi) return {};
    pixelRange(lo, hi, height, box.y0, box.y1);
  }
  return box;
}

namespace {

// The half-spaces of the clip polyhedron ∩ view volume (window space, x ∈ [0, W], y ∈ [0, H],
// z ∈ [0, 1]).
std::vector<Eigen::Vector4d> boundedPolytope(const std::vector<HalfSpace>& clip, int width, int height) {
  std::vector<Eigen::Vector4d> P;
  for (const auto& h : clip) P.push_back(h.p);
  P.push_back({-1, 0, 0, 0});
  P.push_back({1, 0, 0, -double(width)});
  P.push_back({0, -1, 0, 0});
  P.push_back({0, 1, 0, -double(height)});
  P.push_back({0, 0, -1, 0});
  P.push_back({0, 0, 1, -1});
  return P;
}

bool insideTol(const std::vector<Eigen::Vector4d>& P, const Eigen::Vector3d& v) {
  const Eigen::Vector4d X = v.homogeneous();
  for (const auto& p : P) {
    const double mag = std::abs(p[0] * X[0]) + std::abs(p[1] * X[1]) + std::abs(p[2] * X[2]) + std::abs(p[3]);
    if (p.dot(X) > 1e-9 * mag) return false;
  }
  return true;
}

// Vertices of the polytope ∩ {plane = 0} (all vertices when plane is null), within tolerance.
std::vector<Eigen::Vector3d> polytopeVertices(const std::vector<Eigen::Vector4d>& P, const Eigen::Vector4d* plane) {
  std::vector<Eigen::Vector3d> out;
  auto consider = [&](const Eigen::Vector4d& p, const Eigen::Vector4d& q, const Eigen::Vector4d& r) {
    Eigen::Matrix3d A;
    A << p.head<3>().transpose(), q.head<3>().transpose(), r.head<3>().transpose();
    const double scale = p.head<3>().norm() * q.head<3>().norm() * r.head<3>().norm();
    if (!(std::abs(A.determinant()) > 1e-12 * scale)) return;
    const Eigen::Vector3d v = A.inverse() * Eigen::Vector3d(-p[3], -q[3], -r[3]);
    if (v.allFinite() && insideTol(P, v)) out.push_back(v);
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

struct Extent {
  double xmin = std::numeric_limits<double>::infinity(), xmax = -xmin, ymin = xmin, ymax = -xmin;
  void add(const Eigen::Vector3d& v) {
    xmin = std::min(xmin, v.x());
    xmax = std::max(xmax, v.x());
    ymin = std::min(ymin, v.y());
    ymax = std::max(ymax, v.y());
  }
  bool empty() const { return !(xmin <= xmax); }
  ScreenBox box(int width, int height) const {
    if (empty()) return {};
    ScreenBox b;
    pixelRange(xmin, xmax, width, b.x0, b.x1);
    pixelRange(ymin, ymax, height, b.y0, b.y1);
    return b;
  }
};

// Points of the line {a·X = 0, b·X = 0} on the quadric and inside P; a line lying on the
// quadric contributes its ends in P.
void lineCandidates(const Eigen::Matrix4d& Q, const Eigen::Vector4d& a, const Eigen::Vector4d& b,
                    const std::vector<Eigen::Vector4d>& P, const Eigen::Vector3d& ref, Extent& ext) {
  const Eigen::Vector3d na = a.head<3>(), nb = b.head<3>();
  const Eigen::Vector3d d = na.cross(nb);
  if (!(d.norm() > 1e-12 * na.norm() * nb.norm())) return;
  Eigen::Matrix3d A;
  A << na.transpose(), nb.transpose(), d.transpose();
  const Eigen::Vector3d X0 = A.partialPivLu().solve(Eigen::Vector3d(-a[3], -b[3], d.dot(ref)));
  if (!X0.allFinite()) return;
  const Eigen::Vector4d H0 = X0.homogeneous(), D(d.x(), d.y(), d.z(), 0);
  const double qa = D.dot(Q * D), qb = D.dot(Q * H0), qc = H0.dot(Q * H0);
  const double scale = Q.cwiseAbs().maxCoeff() * (H0.squaredNorm() + D.squaredNorm());
  if (std::abs(qa) <= 1e-13 * scale && std::abs(qb) <= 1e-13 * scale && std::abs(qc) <= 1e-13 * scale) {
    // The whole line is on the quadric: its ends inside P.
    double lo = -std::numeric_limits<double>::infinity(), hi = -lo;
    for (const auto& p : P) {
      const double al = p.dot(D), be = p.dot(H0);
      if (al > 0) hi = std::min(hi, -be / al);
      else if (al < 0) lo = std::max(lo, -be / al);
      else if (be > 0) return;
    }
    if (lo <= hi && std::isfinite(lo) && std::isfinite(hi)) {
      ext.add(X0 + lo * d);
      ext.add(X0 + hi * d);
    }
    return;
  }
  const QuadraticRoots r = stableRoots(qa, qb, qc);
  for (int i = 0; i < r.count; ++i) {
    const Eigen::Vector3d v = X0 + r.r[i] * d;
    if (v.allFinite() && insideTol(P, v)) ext.add(v);
  }
}

}  // namespace

static ScreenBox polytopeBoxOnPlane(const std::vector<HalfSpace>& clip, int width, int height,
                             const Eigen::Vector4d* plane) {
  const std::vector<Eigen::Vector4d> P = boundedPolytope(clip, width, height);
  Extent ext;
  for (const auto& v : polytopeVertices(P, plane)) {
    if (!plane) {
      ext.add(v);
      continue;
    }
    const Eigen::Vector4d& q = *plane;
    const double mag = std::abs(q[0] * v[0]) + std::abs(q[1] * v[1]) + std::abs(q[2] * v[2]) + std::abs(q[3]);
    if (std::abs(q.dot(v.homogeneous())) <= 1e-9 * mag) ext.add(v);
  }
  return ext.box(width, height);
}

ScreenBox polytopeBox(const std::vector<HalfSpace>& clip, int width, int height) {
  return polytopeBoxOnPlane(clip, width, height, nullptr);
}

ScreenBox patchBox(const Eigen::Matrix4d& Q, const std::vector<HalfSpace>& clip, bool solid, int width,
                   int height) {
  const std::vector<Eigen::Vector4d> P = boundedPolytope(clip, width, height);
  const Eigen::Vector3d ref(width / 2.0, height / 2.0, 0.5);
  const Eigen::Matrix<double, 3, 4> G = Q.topRows<3>();  // ∇f / 2 = G X
  Extent ext;
  const Eigen::Vector3d axes[2] = {Eigen::Vector3d::UnitX(), Eigen::Vector3d::UnitY()};
  for (int ax = 0; ax < 2; ++ax) {
    // (a) ∇f parallel to the axis: the two other gradient components vanish.
    const int o1 = ax == 0 ? 1 : 0;
    lineCandidates(Q, G.row(o1).transpose(), G.row(2).transpose(), P, ref, ext);
    // (b) on each face: ∇f · (n × axis) = 0.
    for (const auto& p : P) {
      const Eigen::Vector3d m = p.head<3>().cross(axes[ax]);
      if (m.norm() <= 1e-12 * p.head<3>().norm()) continue;  // face ⟂ axis: its edges bound it
      lineCandidates(Q, p, (m.transpose() * G).transpose(), P, ref, ext);
    }
  }
  // (c) each edge of the polytope against the surface.
  for (std::size_t i = 0; i < P.size(); ++i)
    for (std::size_t j = i + 1; j < P.size(); ++j) lineCandidates(Q, P[i], P[j], P, ref, ext);
  // The singular point of a cone.
  const Eigen::Matrix3d E = Q.topLeftCorner<3, 3>();
  Eigen::FullPivLU<Eigen::Matrix3d> lu(E);
  if (lu.isInvertible()) {
    const Eigen::Vector3d apex = lu.solve(Eigen::Vector3d(-Q.block<3, 1>(0, 3)));
    const Eigen::Vector4d H = apex.homogeneous();
    if (apex.allFinite() && std::abs(H.dot(Q * H)) <= 1e-9 * Q.cwiseAbs().maxCoeff() * H.squaredNorm() &&
        insideTol(P, apex))
      ext.add(apex);
  }
  // Solids: corners of the caps.
  if (solid) {
    for (const auto& v : polytopeVertices(P, nullptr)) {
      const Eigen::Vector4d H = v.homogeneous();
      if (H.dot(Q * H) <= 1e-9 * Q.cwiseAbs().maxCoeff() * H.squaredNorm()) ext.add(v);
    }
  }
  return ext.box(width, height);
}

ScreenBox worldBoxToScreen(const Eigen::AlignedBox3d& wb, const Eigen::Matrix4d& M, int width, int height) {
  if (wb.isEmpty()) return {};
  double xmin = std::numeric_limits<double>::infinity(), xmax = -xmin, ymin = xmin, ymax = -xmin;
  for (int i = 0; i < 8; ++i) {
    const Eigen::Vector4d X = M * wb.corner(Eigen::AlignedBox3d::CornerType(i)).homogeneous();
    if (!(X[3] > 0)) return screen(width, height);
    xmin = std::min(xmin, X[0] / X[3]);
    xmax = std::max(xmax, X[0] / X[3]);
    ymin = std::min(ymin, X[1] / X[3]);
    ymax = std::max(ymax, X[1] / X[3]);
  }
  ScreenBox box;
  pixelRange(xmin, xmax, width, box.x0, box.x1);
  pixelRange(ymin, ymax, height, box.y0, box.y1);
  return box;
}

WindowPrimitive toWindow(const Primitive& prim, int index, const Eigen::Matrix4d& Minv, int width, int height) {
  WindowPrimitive w;
  w.index = index;
  w.solid = prim.solid;
  w.material = prim.material;
  w.object = prim.object;
  const Quadric qw = prim.quadric.transformedByInverse(Minv).normalized();
  w.Q = qw.Q;
  w.clip.reserve(prim.clip.size());
  for (const auto& h : prim.clip) {
    const HalfSpace t = h.transformedByInverse(Minv);
    w.clip.emplace_back(normalisedPlane(t.p), t.owns_boundary);
  }
  if (prim.isPlanar() && !prim.solid) {
    // A plane f = p·X (times the weight) in world space: restrict the polytope to it.
    const Eigen::Vector4d p(2 * prim.quadric.Q(0, 3), 2 * prim.quadric.Q(1, 3), 2 * prim.quadric.Q(2, 3),
                            prim.quadric.Q(3, 3));
    const Eigen::Vector4d pw = normalisedPlane(Minv.transpose() * p);
    w.box = polytopeBoxOnPlane(w.clip, width, height, &pw);
    return w;
  }
  const ScreenBox piece = patchBox(w.Q, w.clip, w.solid, width, height);
  if (w.solid && !(w.a() > 0)) {
    w.box = piece;  // caps can show where the line never meets the surface
  } else {
    w.box = conicBox(w.contour(), width, height).intersect(piece);
  }
  return w;
}

}  // namespace qacc
