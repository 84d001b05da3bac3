// Per-direction grid densities from the projected curvature (grid_density.h).
#include "modeling/tessellation/grid_density.h"

#include <algorithm>
#include <cmath>

#include "modeling/tessellation/screen_error.h"

namespace qacc::tess {

namespace {

constexpr int kProbeU = 48, kProbeV = 32;
constexpr double kTwoPi = 2.0 * M_PI;
// Share of ε given to each direction (two directions: ε/2 each), with a margin for the
// variation of the curvature between probe samples.
constexpr double kShare = 0.45;

}  // namespace

ProjectedCurvature projectedCurvature(const Domain& domain, const Quadric& q, double v0, double v1,
                                      const std::vector<HalfSpace>& planes, const ScreenView& view) {
  const Matrix3d H = 2.0 * q.Q.topLeftCorner<3, 3>();
  const double hu = 1e-6 * kTwoPi, hv = 1e-6 * std::max(std::abs(v1 - v0), 1e-300);
  // Image margin: samples a little off screen still shape triangles that reach it.
  const double margin = 0.1 * std::max(view.width, view.height);
  // Tiers: kept by the planes and on screen; kept by the planes and in front of the near
  // plane; in front of the near plane. The first tier with a sample decides.
  ProjectedCurvature tier[3];
  for (int j = 0; j < kProbeV; ++j)
    for (int i = 0; i < kProbeU; ++i) {
      const double u = kTwoPi * (i + 0.5) / kProbeU, v = v0 + (v1 - v0) * (j + 0.5) / kProbeV;
      const Vector3d p = domain.position(Vector3d(u, v, 0));
      if (!p.allFinite() || !view.inFront(p)) continue;
      const Vector3d g = q.gradient(p);
      const double gn = g.norm();
      if (!(gn > 1e-12 * (1 + p.norm()))) continue;
      const Vector3d pu = (domain.position(Vector3d(u + hu, v, 0)) - domain.position(Vector3d(u - hu, v, 0))) / (2 * hu);
      const Vector3d pv = (domain.position(Vector3d(u, v + hv, 0)) - domain.position(Vector3d(u, v - hv, 0))) / (2 * hv);
      const double L = std::abs(pu.dot(H * pu)) / gn, N = std::abs(pv.dot(H * pv)) / gn,
                   M = std::abs(pu.dot(H * pv)) / gn;
      const double s = view.pixelsPerUnit(p);
      bool kept = true;
      for (const auto& h : planes)
        if (kept && !h.keeps(h.eval(p))) kept = false;
      const int t = kept ? (view.onScreen(p, margin) ? 0 : 1) : 2;
      for (int k = t; k < 3; ++k) {
        tier[k].au = std::max(tier[k].au, s * (L + M));
        tier[k].av = std::max(tier[k].av, s * (N + M));
        tier[k].seen = true;
      }
    }
  for (const ProjectedCurvature& c : tier)
    if (c.seen) return c;
  return ProjectedCurvature{};
}

Grid gridForPixelError(const ProjectedCurvature& c, double v0, double v1, double epsilon, double scale) {
  auto count = [&](double a, double range, int least) {
    if (!(a > 0)) return least;
    const double step = std::sqrt(8.0 * kShare * epsilon / a);
    const double n = std::ceil(scale * std::abs(range) / step);
    return int(std::clamp(n, double(least), 1e6));
  };
  Grid g;
  g.nu = count(c.au, kTwoPi, 3);
  g.nv = count(c.av, v1 - v0, 1);
  return g;
}

}  // namespace qacc::tess
