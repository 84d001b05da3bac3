#include "modeling/tessellation/surface_clipping.h"

#include <algorithm>
#include <cmath>

namespace qacc::tess {

bool lexLess(const Vector3d& a, const Vector3d& b) {
  if (a.x() != b.x()) return a.x() < b.x();
  if (a.y() != b.y()) return a.y() < b.y();
  return a.z() < b.z();
}

Vector3d Domain::ontoCurve(const Vector3d& x0, const HalfSpace& h, double reach) const {
  const Vector3d n = h.p.head<3>().normalized();
  Vector3d x = x0;
  for (int it = 0; it < 8; ++it) {
    const Vector3d g = surface->gradient(x);
    const Vector3d gt = g - g.dot(n) * n;
    const double g2 = gt.squaredNorm();
    if (!(g2 > 0)) return x0;
    const Vector3d step = surface->eval(x) * gt / g2;
    x -= step;
    if (!x.allFinite() || (x - x0).norm() > reach) return x0;
    if (step.norm() <= 1e-15 * (1 + x.norm())) break;
  }
  return x;
}

Vector3d Domain::ontoCorner(const Vector3d& x, const HalfSpace& h1, const HalfSpace& h2, double reach) const {
  const Vector3d d = h1.p.head<3>().cross(h2.p.head<3>());
  const double dn = d.norm();
  if (!(dn > 0)) return x;
  const Vector3d e = d / dn;
  // f(x + s e) = f(x) + s ∇f·e + s² eᵀ Q₃ e
  const double a = e.dot(surface->Q.topLeftCorner<3, 3>() * e), b = surface->gradient(x).dot(e), c = surface->eval(x);
  double s = 0;
  if (std::abs(a) <= 1e-14 * (std::abs(b) + 1e-300)) {
    if (!(std::abs(b) > 0)) return x;
    s = -c / b;
  } else {
    const double disc = b * b - 4 * a * c;
    if (disc < 0) return x;
    const double qq = -0.5 * (b + std::copysign(std::sqrt(disc), b));
    const double r1 = qq / a, r2 = qq != 0 ? c / qq : r1;
    s = std::abs(r1) < std::abs(r2) ? r1 : r2;
  }
  if (!std::isfinite(s) || std::abs(s) > reach) return x;
  return x + s * e;
}

void clipPolygon(Polygon& poly, Polygon& out, const Domain& d, const std::vector<HalfSpace>& planes) {
  // Per vertex of the current polygon: kept by the current plane. At most 32 + planes
  // vertices (each plane adds at most one), so a fixed buffer past 64 is never needed.
  std::vector<char> keptHeap;
  char keptLocal[64];
  for (std::size_t k = 0; k < planes.size() && !poly.empty(); ++k) {
    const unsigned bit = k < 32 ? (1u << k) : 0u;
    char* kept = keptLocal;
    if (poly.size() > sizeof keptLocal) {
      keptHeap.assign(poly.size(), 0);
      kept = keptHeap.data();
    }
    bool all = true, none = true;
    for (std::size_t i = 0; i < poly.size(); ++i) {
      kept[i] = (poly[i].tags & bit) ? 1 : char(planes[k].keeps(planes[k].eval(poly[i].pos)));
      all = all && kept[i];
      none = none && !kept[i];
    }
    if (all) continue;
    if (none) {
      poly.clear();
      return;
    }
    out.clear();
    for (std::size_t i = 0; i < poly.size(); ++i) {
      const std::size_t j = (i + 1) % poly.size();
      if (kept[i]) out.push_back(poly[i]);
      if (kept[i] != kept[j]) {
        ClipVertex v;
        v.coord = d.cut(poly[i].coord, poly[j].coord, poly[i].pos, poly[j].pos, planes[k]);
        v.tags = (poly[i].tags & poly[j].tags) | bit;
        if (d.linear && d.surface) {  // onto the surface: along the plane, or a corner's line
          const double reach = (poly[j].coord - poly[i].coord).norm();
          unsigned other = 0;
          for (std::size_t m = 0; m < planes.size() && m < 32; ++m)
            if (m != k && (v.tags & (1u << m))) other = unsigned(m) + 1;
          v.coord = other ? d.ontoCorner(v.coord, planes[other - 1], planes[k], reach)
                          : d.ontoCurve(v.coord, planes[k], reach);
        }
        if (!d.linear && (v.tags & ~bit)) {  // a corner: on the surface and on two planes
          for (std::size_t m = 0; m < planes.size() && m < 32; ++m)
            if (m != k && (v.tags & (1u << m))) {
              v.coord = d.corner(v.coord, planes[m], planes[k]);
              break;
            }
        }
        v.pos = d.position(v.coord);
        out.push_back(v);
      }
    }
    poly.swap(out);
  }
  if (poly.size() < 3) poly.clear();
}

}  // namespace qacc::tess
