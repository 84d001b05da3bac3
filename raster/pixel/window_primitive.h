// WindowPrimitive: a Primitive carried to window space (design §2) for scan conversion.
//
// With points mapping as X_win ~ M X_world (M = Camera::worldToWindow), the quadric is
// Q' = M⁻ᵀ Q M⁻¹ and each half-space p' = M⁻ᵀ p. Inside the view volume (0 <= z <= 1) the
// homogeneous weight of the corresponding world point is positive, so the signs of f and of
// every half-space are preserved (f scales by w² > 0, planes by w > 0). Both are normalised
// by positive factors (same surface, same sides).
//
// Along the line of pixel (x, y): f(z) = a z² + 2 b z + c with a = Q'33 (z row/column),
// b = Q'13 x + Q'23 y + Q'34, c quadratic in (x, y) (digest §1, derived for screen space).
// The contour conic is Δ(x, y) = b² − a c; a pixel can see the surface only where Δ >= 0.
#pragma once
#include <vector>

#include <Eigen/Dense>

#include "modeling/geometry/half_space.h"
#include "modeling/geometry/primitive.h"
#include "raster/pixel/screen_box.h"

namespace qacc {

// Δ(x, y) = A x² + 2B xy + C y² + 2D x + 2E y + F.
struct Conic {
  double A = 0, B = 0, C = 0, D = 0, E = 0, F = 0;
  double operator()(double x, double y) const {
    return A * x * x + 2 * B * x * y + C * y * y + 2 * D * x + 2 * E * y + F;
  }
};

struct WindowPrimitive {
  int index = 0;  // index of the source primitive in Scene::primitives
  Eigen::Matrix4d Q = Eigen::Matrix4d::Zero();  // window-space quadric, max |coef| = 1
  std::vector<HalfSpace> clip;                  // window-space half-spaces, normalised
  bool solid = false;
  int material = 0;
  int object = 0;
  ScreenBox box;  // pixels that can show this primitive (empty: cannot be seen)
  // The view volume's faces the piece cannot reach, known from its world bounds (bit i: the
  // i-th of x >= 0, x <= W, y >= 0, y <= H, z >= 0, z <= 1): their candidates are not cut.
  unsigned unreachable_view_faces = 0;

  double a() const { return Q(2, 2); }
  double b(double x, double y) const { return Q(0, 2) * x + Q(1, 2) * y + Q(2, 3); }
  double c(double x, double y) const {
    return Q(0, 0) * x * x + 2 * Q(0, 1) * x * y + Q(1, 1) * y * y + 2 * Q(0, 3) * x + 2 * Q(1, 3) * y + Q(3, 3);
  }
  Conic contour() const;  // Δ = b² − a c as a conic in (x, y)
};

// Window-space form of `prim` for a width x height image; M = world → window, Minv = M⁻¹.
// `extentXY`, when given, receives the window-space extent the screen box was made from (a
// planar primitive's polygon vertices, or the piece's x and y candidates), which
// pieceDepthRange then completes with the z candidates alone. A primitive whose world box
// the loader recorded (knownWorldBox) skips the candidates on the view volume's faces that
// box keeps it from (unreachable_view_faces): the same box, from fewer candidates.
WindowPrimitive toWindow(const Primitive& prim, int index, const Eigen::Matrix4d& M, const Eigen::Matrix4d& Minv,
                         int width, int height, Eigen::AlignedBox3d* extentXY = nullptr);
// The view faces (WindowPrimitive::unreachable_view_faces) that `prim`'s recorded world box
// keeps its piece from: the box carried to window space (its corners' images, all in front
// of the eye) inside each face by a margin — the view culling's two pixels
// (ViewVolume::kMarginPixels) on the screen's edges, 1e-4 + 1e-8 (width + height) in depth,
// both far above the candidates' tolerance (insidePolytope). 0 without a valid record.
unsigned unreachableViewFaces(const Primitive& prim, const Eigen::Matrix4d& M, int width, int height);

// Pixels covering the window-space projection of the clipped piece itself: the exact x and y
// extents of (surface ∩ clip polyhedron ∩ view volume), or of (solid ∩ ...) when `solid`,
// found among the points where a linear function can be extreme on that set (Lagrange):
// surface points where ∇f ∥ the axis, points of each face's conic where ∇f, the face
// normal and the axis are coplanar, face-edge ∩ surface, the singular point (cone apex) and,
// for solids, the polytope vertices inside f <= 0. Widened by one pixel; empty when nothing
// of the piece lies in the view volume.
ScreenBox patchBox(const Eigen::Matrix4d& Q, const std::vector<HalfSpace>& clip, bool solid, int width, int height);
// The window depth range [lo, hi] of the same set as the screen box (the clipped piece, or
// the solid's part of the clip polyhedron, or a planar primitive's polygon, inside the view
// volume), from the same exact candidates (Lagrange, modeling/geometry/piece_extent.h) along
// z; lo > hi when the set is empty. `w` is toWindow(prim, ...); `extentXY`, when given, is
// the extent that toWindow returned for it (the same range, from fewer candidates).
struct DepthRange {
  double lo = 1, hi = 0;
};
DepthRange pieceDepthRange(const Primitive& prim, const WindowPrimitive& w, const Eigen::Matrix4d& Minv, int width,
                           int height, const Eigen::AlignedBox3d* extentXY = nullptr);
// Pixels whose centres can satisfy Δ >= 0 (exact extent of the conic region, widened by one
// pixel against rounding), clamped to the screen; the whole screen when the region is unbounded.
ScreenBox conicBox(const Conic& delta, int width, int height);
// Pixels covering the projection of the clip polyhedron ∩ view volume (its vertices are
// enumerated exactly), widened by one pixel; empty when that polytope is empty.
ScreenBox polytopeBox(const std::vector<HalfSpace>& clip, int width, int height);
// Pixels covering the window-space projection of a world box (whole screen if it reaches
// behind the eye).
ScreenBox worldBoxToScreen(const Eigen::AlignedBox3d& box, const Eigen::Matrix4d& M, int width, int height);

}  // namespace qacc
