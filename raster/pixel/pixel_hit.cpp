#include "raster/pixel/pixel_hit.h"

#include "modeling/geometry/stable_roots.h"

namespace qacc {
namespace {

bool keptByAll(const WindowPrimitive& w, double x, double y, double z, int except) {
  const Eigen::Vector4d X(x, y, z, 1);
  for (int i = 0; i < int(w.clip.size()); ++i)
    if (i != except && !w.clip[std::size_t(i)].keeps(w.clip[std::size_t(i)].evalHomogeneous(X))) return false;
  return true;
}

}  // namespace

bool pixelHit(const WindowPrimitive& w, double x, double y, PixelHit& hit) {
  const double a = w.a(), b = w.b(x, y), c = w.c(x, y);
  if (w.solid) {
    // Entry into the clip polyhedron along the line: the largest lower bound.
    double lo = 0;
    int loPlane = -1;
    double hi = 1;
    for (int i = 0; i < int(w.clip.size()); ++i) {
      const Eigen::Vector4d& p = w.clip[std::size_t(i)].p;
      const double al = p[2], be = p[0] * x + p[1] * y + p[3];
      if (al < 0) {
        const double t = -be / al;
        if (t > lo) {
          lo = t;
          loPlane = i;
        }
      } else if (al > 0) {
        hi = std::min(hi, -be / al);
      } else if (!w.clip[std::size_t(i)].keeps(be)) {
        return false;
      }
    }
    if (lo > hi) return false;
    if (loPlane >= 0 && a * lo * lo + 2 * b * lo + c <= 0 && keptByAll(w, x, y, lo, loPlane)) {
      hit.z = lo;
      hit.cap = loPlane;
      return true;
    }
  }
  const QuadraticRoots r = stableRoots(a, b, c);
  for (int i = 0; i < r.count; ++i) {
    const double z = r.r[i];
    if (z >= 0 && z <= 1 && keptByAll(w, x, y, z, -1)) {
      hit.z = z;
      hit.cap = -1;
      return true;
    }
  }
  return false;
}

}  // namespace qacc
