#include "raster/pixel/window_primitive.h"

#include <algorithm>
#include <cmath>
#include <limits>

#include "modeling/geometry/piece_extent.h"
#include "modeling/geometry/primitive_bounds.h"
#include "modeling/geometry/stable_roots.h"
#include "modeling/geometry/unit_plane.h"
#include "modeling/scene/view_volume.h"

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

// Pixels whose centres can lie in the (x, y) extent of a window-space box.
ScreenBox pixelBox(const Eigen::AlignedBox3d& ext, int width, int height) {
  if (ext.isEmpty()) return {};
  ScreenBox b;
  pixelRange(ext.min().x(), ext.max().x(), width, b.x0, b.x1);
  pixelRange(ext.min().y(), ext.max().y(), height, b.y0, b.y1);
  return b;
}

}  // namespace

// A planar primitive's plane f = p·X (times the weight) in window space.
static Eigen::Vector4d windowPlane(const Primitive& prim, const Eigen::Matrix4d& Minv) {
  const Eigen::Vector4d p(2 * prim.quadric.Q(0, 3), 2 * prim.quadric.Q(1, 3), 2 * prim.quadric.Q(2, 3),
                          prim.quadric.Q(3, 3));
  return unitPlane(Minv.transpose() * p);
}

// The vertices of the clip polyhedron ∩ view volume on `plane` (all of them when null).
static std::vector<Eigen::Vector3d> polytopeVerticesOnPlane(const std::vector<HalfSpace>& clip, int width, int height,
                                                            const Eigen::Vector4d* plane) {
  std::vector<Eigen::Vector3d> out;
  for (const auto& v : polytopeVertices(boundedPolytope(clip, width, height), plane)) {
    if (plane) {
      const Eigen::Vector4d& q = *plane;
      const double mag = std::abs(q[0] * v[0]) + std::abs(q[1] * v[1]) + std::abs(q[2] * v[2]) + std::abs(q[3]);
      if (!(std::abs(q.dot(v.homogeneous())) <= 1e-9 * mag)) continue;
    }
    out.push_back(v);
  }
  return out;
}

// The box of the vertices of the clip polyhedron ∩ view volume on `plane` (all when null).
static Eigen::AlignedBox3d polytopeExtentOnPlane(const std::vector<HalfSpace>& clip, int width, int height,
                                                 const Eigen::Vector4d* plane) {
  Eigen::AlignedBox3d ext;
  for (const auto& v : polytopeVerticesOnPlane(clip, width, height, plane)) ext.extend(v);
  return ext;
}

ScreenBox polytopeBox(const std::vector<HalfSpace>& clip, int width, int height) {
  return pixelBox(polytopeExtentOnPlane(clip, width, height, nullptr), width, height);
}

// The anchor of the candidate lines of a window-space piece: the middle of the view volume.
static Eigen::Vector3d viewCentre(int width, int height) { return {width / 2.0, height / 2.0, 0.5}; }

// The view faces of boundedPolytope(clip, ...), which follow the clip planes, as P's planes.
static UnreachablePlanes viewFaces(const std::vector<HalfSpace>& clip, unsigned faces) {
  return {clip.size(), faces};
}

// The piece's extent from the candidates of x and y (pieceExtent, axes 2).
static Eigen::AlignedBox3d pieceExtentXY(const Eigen::Matrix4d& Q, const std::vector<HalfSpace>& clip, bool solid,
                                         int width, int height, unsigned unreachableFaces = 0) {
  return pieceExtent(Q, boundedPolytope(clip, width, height), solid, viewCentre(width, height), 2,
                     viewFaces(clip, unreachableFaces));
}

ScreenBox patchBox(const Eigen::Matrix4d& Q, const std::vector<HalfSpace>& clip, bool solid, int width,
                   int height) {
  return pixelBox(pieceExtentXY(Q, clip, solid, width, height), width, height);
}

// The window-space box [lo, hi] of a world box's image, from its 8 corners carried by M.
// False when a corner lies on or behind the eye's plane (w <= 0): the image is then not inside
// the corners' hull. `finite` tells whether every corner's image is finite.
static bool windowImageBox(const Eigen::AlignedBox3d& wb, const Eigen::Matrix4d& M, Eigen::Vector3d& lo,
                           Eigen::Vector3d& hi, bool& finite) {
  lo = Eigen::Vector3d::Constant(std::numeric_limits<double>::infinity());
  hi = -lo;
  finite = true;
  for (int i = 0; i < 8; ++i) {
    const Eigen::Vector4d X = M * wb.corner(Eigen::AlignedBox3d::CornerType(i)).homogeneous();
    if (!(X[3] > 0)) return false;
    for (int k = 0; k < 3; ++k) {
      const double x = X[k] / X[3];
      finite = finite && std::isfinite(x);
      lo[k] = std::min(lo[k], x);
      hi[k] = std::max(hi[k], x);
    }
  }
  return true;
}

unsigned unreachableViewFaces(const Primitive& prim, const Eigen::Matrix4d& M, int width, int height) {
  const Eigen::AlignedBox3d* wb = knownWorldBox(prim);
  Eigen::Vector3d lo, hi;
  bool finite = false;
  if (!wb || !windowImageBox(*wb, M, lo, hi, finite) || !finite) return 0;
  // The margins stand far above what a candidate on a face could be off by: insidePolytope
  // accepts a point outside a plane by 1e-9 of the plane's terms, at most about
  // 1e-9 (width + height) in window units along the plane's normal, which may lie in z.
  const double px = ViewVolume::kMarginPixels, dz = 1e-4 + 1e-8 * (double(width) + double(height));
  unsigned faces = 0;
  if (lo.x() > px) faces |= 1u;
  if (hi.x() < width - px) faces |= 2u;
  if (lo.y() > px) faces |= 4u;
  if (hi.y() < height - px) faces |= 8u;
  if (lo.z() > dz) faces |= 16u;
  if (hi.z() < 1 - dz) faces |= 32u;
  return faces;
}

ScreenBox worldBoxToScreen(const Eigen::AlignedBox3d& wb, const Eigen::Matrix4d& M, int width, int height) {
  if (wb.isEmpty()) return {};
  Eigen::Vector3d lo, hi;
  bool finite;
  if (!windowImageBox(wb, M, lo, hi, finite)) return screen(width, height);
  ScreenBox box;
  pixelRange(lo.x(), hi.x(), width, box.x0, box.x1);
  pixelRange(lo.y(), hi.y(), height, box.y0, box.y1);
  return box;
}

DepthRange pieceDepthRange(const Primitive& prim, const WindowPrimitive& w, const Eigen::Matrix4d& Minv, int width,
                           int height, const Eigen::AlignedBox3d* extentXY) {
  DepthRange r;
  if (prim.isPlanar() && !prim.solid) {
    // The polygon's vertices: their z range, with the initial lo = 1, hi = 0 of an empty range.
    Eigen::AlignedBox3d ext;
    if (extentXY) {
      ext = *extentXY;
    } else {
      const Eigen::Vector4d pw = windowPlane(prim, Minv);
      ext = polytopeExtentOnPlane(w.clip, width, height, &pw);
    }
    if (!ext.isEmpty()) {
      r.lo = std::min(r.lo, ext.min().z());
      r.hi = std::max(r.hi, ext.max().z());
    }
    return r;
  }
  Eigen::AlignedBox3d ext;
  if (extentXY) {
    ext = *extentXY;
    addAxisCandidates(w.Q, boundedPolytope(w.clip, width, height), viewCentre(width, height), 2, ext,
                      viewFaces(w.clip, w.unreachable_view_faces));
  } else {
    ext = pieceExtent(w.Q, boundedPolytope(w.clip, width, height), w.solid, viewCentre(width, height), 3,
                      viewFaces(w.clip, w.unreachable_view_faces));
  }
  if (!ext.isEmpty()) {
    r.lo = ext.min().z();
    r.hi = ext.max().z();
  }
  return r;
}

WindowPrimitive toWindow(const Primitive& prim, int index, const Eigen::Matrix4d& M, const Eigen::Matrix4d& Minv,
                         int width, int height, Eigen::AlignedBox3d* extentXY) {
  WindowPrimitive w;
  w.index = index;
  w.solid = prim.solid;
  w.material = prim.material;
  w.object = prim.object;
  const Quadric qw = prim.quadric.transformedByInverse(Minv).normalized();
  w.Q = qw.Q;
  w.clip.reserve(prim.clip.size());
  for (const auto& h : prim.clip) {
    const HalfSpace t = unitPlane(h).transformedByInverse(Minv);
    // Scaled by powers of two (unit_plane.h), in world space so that no transform overflows
    // and in window space: exact, so a plane through pixel centres stays zero there, and
    // sign-symmetric, so a plane and its opposite stay exact negations.
    w.clip.emplace_back(unitPlane(t.p), t.owns_boundary);
  }
  if (prim.isPlanar() && !prim.solid) {
    const Eigen::Vector4d pw = windowPlane(prim, Minv);
    const Eigen::AlignedBox3d ext = polytopeExtentOnPlane(w.clip, width, height, &pw);
    if (extentXY) *extentXY = ext;
    w.box = pixelBox(ext, width, height);
    return w;
  }
  w.unreachable_view_faces = unreachableViewFaces(prim, M, width, height);
  const Eigen::AlignedBox3d ext = pieceExtentXY(w.Q, w.clip, w.solid, width, height, w.unreachable_view_faces);
  if (extentXY) *extentXY = ext;
  const ScreenBox piece = pixelBox(ext, width, height);
  if (w.solid && !(w.a() > 0)) {
    w.box = piece;  // caps can show where the line never meets the surface
  } else {
    w.box = conicBox(w.contour(), width, height).intersect(piece);
  }
  return w;
}

}  // namespace qacc
