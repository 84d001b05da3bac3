#include "hw_model/datapath/span_solver.h"

#include <algorithm>
#include <cmath>

namespace qacc {

int solveSpans(const PrimitiveSetup& s, int y, int xlo, int xhi, Span out[2]) {
  const int lo = std::max(xlo, s.x0), hi = std::min(xhi, s.x1);
  if (lo >= hi || y < s.y0 || y >= s.y1) return 0;
  if (s.fullRows) {
    out[0] = {lo, hi};
    return 1;
  }
  // Δ along the row (local u): α u² + β u + γ >= 0.
  const double v = y - s.y0;
  const double al = s.tA, be = s.tB * v + s.tD, ga = (s.tC * v + s.tE) * v + s.tF;
  const double ox = s.x0;
  auto clampSpan = [&](double a, double b, Span& sp) {  // local [a, b] → screen, widened
    const double A = std::floor(a) - 1 + ox, B = std::ceil(b) + 2 + ox;
    sp.x0 = int(std::max<double>(lo, std::min<double>(hi, A)));
    sp.x1 = int(std::max<double>(lo, std::min<double>(hi, B)));
    return sp.x1 > sp.x0;
  };
  const double inf = 1e30;
  int n = 0;
  const double scale = std::fabs(al) + std::fabs(be) + std::fabs(ga);
  if (std::fabs(al) <= 1e-14 * scale) {  // linear along the row
    if (std::fabs(be) <= 1e-14 * scale) {
      if (ga >= -1e-9 * scale) out[n++] = {lo, hi};
      return n;
    }
    const double r = -ga / be;
    Span sp;
    if (be > 0 ? clampSpan(std::max(-inf, r), inf, sp) : clampSpan(-inf, std::min(inf, r), sp)) out[n++] = sp;
    return n;
  }
  const double disc = be * be - 4 * al * ga;
  if (disc < 0) {
    if (al > 0) out[n++] = {lo, hi};
    return n;
  }
  const double sq = std::sqrt(disc);
  const double q = -0.5 * (be + std::copysign(sq, be));
  double r1 = q / al, r2 = q != 0 ? ga / q : r1;
  if (r1 > r2) std::swap(r1, r2);
  Span sp;
  if (al < 0) {
    if (clampSpan(r1, r2, sp)) out[n++] = sp;
    return n;
  }
  Span a, b;
  const bool ha = clampSpan(-inf, r1, a), hb = clampSpan(r2, inf, b);
  if (ha && hb && a.x1 >= b.x0) {
    out[n++] = {a.x0, std::max(a.x1, b.x1)};
  } else {
    if (ha) out[n++] = a;
    if (hb) out[n++] = b;
  }
  return n;
}

}  // namespace qacc
