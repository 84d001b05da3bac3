#include "raster/pixel/solid_intervals.h"

#include <limits>

#include "modeling/geometry/stable_roots.h"

namespace qacc {

int solidIntervals(const WindowPrimitive& w, double x, double y, DepthInterval out[2]) {
  // The clip polyhedron along the line, within the view volume: [lo, hi].
  DepthBound lo{0, DepthBound::kView}, hi{1, DepthBound::kView};
  for (int i = 0; i < int(w.clip.size()); ++i) {
    const Eigen::Vector4d& p = w.clip[std::size_t(i)].p;
    const double al = p[2], be = p[0] * x + p[1] * y + p[3];
    if (al < 0) {
      const double t = -be / al;
      if (t > lo.z) lo = {t, i};
    } else if (al > 0) {
      const double t = -be / al;
      if (t < hi.z) hi = {t, i};
    } else if (!w.clip[std::size_t(i)].keeps(be)) {
      return 0;
    }
  }
  if (lo.z > hi.z) return 0;

  // {f <= 0} along the line: up to two pieces, unbounded ends at ±infinity.
  const double inf = std::numeric_limits<double>::infinity();
  const double a = w.a(), b = w.b(x, y), c = w.c(x, y);
  double piece[2][2];
  int pieces = 0;
  const QuadraticRoots r = stableRoots(a, b, c);
  if (r.count == 2) {
    if (a > 0) {
      piece[pieces][0] = r.r[0], piece[pieces++][1] = r.r[1];
    } else {
      piece[pieces][0] = -inf, piece[pieces++][1] = r.r[0];
      piece[pieces][0] = r.r[1], piece[pieces++][1] = inf;
    }
  } else if (r.count == 1) {
    if (a == 0) {  // linear: 2 b z + c <= 0
      if (b > 0) piece[pieces][0] = -inf, piece[pieces++][1] = r.r[0];
      else piece[pieces][0] = r.r[0], piece[pieces++][1] = inf;
    } else if (a < 0) {  // double root: f <= 0 everywhere
      piece[pieces][0] = -inf, piece[pieces++][1] = inf;
    }
  } else if (a < 0 || (a == 0 && b == 0 && c <= 0)) {
    piece[pieces][0] = -inf, piece[pieces++][1] = inf;
  }

  int n = 0;
  for (int k = 0; k < pieces; ++k) {
    DepthInterval iv;
    // A plane at the same depth as the surface bounds the solid there as a cap (pixelHit's rule).
    iv.in = lo.z >= piece[k][0] ? lo : DepthBound{piece[k][0], DepthBound::kSurface};
    iv.out = hi.z <= piece[k][1] ? hi : DepthBound{piece[k][1], DepthBound::kSurface};
    if (iv.in.z < iv.out.z) out[n++] = iv;  // a tangent point bounds no volume
  }
  return n;
}

}  // namespace qacc
