// Clipping of a surface's polygons by the half-spaces of a primitive (tessellation.h), in
// the surface's own domain (parameters of a natural quadric, or world points): a cut point
// on a parametric edge is found by bisection along it, so it lies on the surface and on the
// plane, and the two polygons sharing an edge get the same point; where a cut lands on two
// planes at once (a corner) it is moved onto both by Newton steps.
#pragma once
#include <functional>
#include <vector>

#include <Eigen/Dense>

#include "modeling/geometry/half_space.h"
#include "modeling/geometry/quadric.h"

namespace qacc::tess {

using Eigen::Vector2d;

// Polygon clipping with plane tags. A vertex carries its domain coordinate (parameters
// (u, v, 0) or a 3-D point), its world position (Domain::position of coord, computed once)
// and a bit mask of the clip planes it lies on.
struct ClipVertex {
  Vector3d coord;
  Vector3d pos;
  unsigned tags = 0;
};
using Polygon = std::vector<ClipVertex>;

// Lexicographic order of points (x, then y, then z): edges and maps keyed by exact position.
bool lexLess(const Vector3d& a, const Vector3d& b);
struct PointKey {
  bool operator()(const Vector3d& a, const Vector3d& b) const { return lexLess(a, b); }
};

// A surface domain: coordinate → world position, and the cut of a domain segment by a plane.
struct Domain {
  std::function<Vector3d(const Vector3d&)> position;
  bool linear = false;  // position() is affine: cut exactly, no bisection
  // Linear domains of a curved surface (marching tetrahedra: world points on chords): the
  // surface (normalised) onto which cut points are moved within their plane, so that a
  // piece's boundary vertices lie on the curve where the surface meets the plane, as the
  // parametric grids' do (shared_boundaries.h); null for planes.
  const Quadric* surface = nullptr;

  // x (on plane h) moved within h onto the surface by Newton steps along the gradient's
  // component in the plane; x unchanged when that does not converge within `reach`.
  Vector3d ontoCurve(const Vector3d& x, const HalfSpace& h, double reach) const;
  // x (on planes h1 and h2) moved along their common line onto the surface (the nearer root
  // of a quadratic); x unchanged when there is none within `reach`.
  Vector3d ontoCorner(const Vector3d& x, const HalfSpace& h1, const HalfSpace& h2, double reach) const;

  // The cut of the domain segment a b (world positions pa, pb) by h.
  Vector3d cut(Vector3d a, Vector3d b, Vector3d pa, Vector3d pb, const HalfSpace& h) const {
    if (lexLess(b, a)) {  // the same edge always gives the same point
      std::swap(a, b);
      std::swap(pa, pb);
    }
    const double ga = h.eval(pa), gb = h.eval(pb);
    if (linear) {
      const double t = ga / (ga - gb);
      return a + std::clamp(t, 0.0, 1.0) * (b - a);
    }
    const bool ka = h.keeps(ga);
    double lo = 0, hi = 1;
    for (int it = 0; it < 52; ++it) {
      const double mid = 0.5 * (lo + hi);
      const bool km = h.keeps(h.eval(position(a + mid * (b - a))));
      if (km == ka) lo = mid; else hi = mid;
    }
    return a + (0.5 * (lo + hi)) * (b - a);
  }

  // Parameters near x where the surface meets both planes (Newton with a numerical
  // Jacobian; x is returned unchanged when it does not converge).
  Vector3d corner(const Vector3d& x0, const HalfSpace& h1, const HalfSpace& h2) const {
    auto F = [&](const Vector3d& x) {
      const Vector3d p = position(x);
      return Vector2d(h1.eval(p) / h1.p.head<3>().norm(), h2.eval(p) / h2.p.head<3>().norm());
    };
    Vector3d x = x0;
    Vector2d r = F(x);
    const double r0 = r.norm();
    for (int it = 0; it < 12 && r.norm() > 1e-14 * (1 + position(x).norm()); ++it) {
      const double e = 1e-7 * (1 + x.head<2>().cwiseAbs().maxCoeff());
      Eigen::Matrix2d Jm;
      Jm.col(0) = (F(x + Vector3d(e, 0, 0)) - F(x - Vector3d(e, 0, 0))) / (2 * e);
      Jm.col(1) = (F(x + Vector3d(0, e, 0)) - F(x - Vector3d(0, e, 0))) / (2 * e);
      if (!(std::abs(Jm.determinant()) > 0)) break;
      const Vector2d step = Jm.partialPivLu().solve(r);
      x -= Vector3d(step.x(), step.y(), 0);
      r = F(x);
    }
    return (r.allFinite() && r.norm() < r0 && (x - x0).norm() < 0.5) ? x : x0;
  }
};

// `poly` replaced by the polygon kept by all of `planes` (emptied when fewer than 3 vertices
// remain). Vertices already tagged as lying on a plane are kept by it. `scratch` is working
// space, passed in so that a builder clipping many polygons allocates once.
void clipPolygon(Polygon& poly, Polygon& scratch, const Domain& d, const std::vector<HalfSpace>& planes);

}  // namespace qacc::tess
