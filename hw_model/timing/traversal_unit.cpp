#include "hw_model/timing/traversal_unit.h"

#include "hw_model/engines/pixel_trace.h"

#include <algorithm>
#include <cmath>

namespace qacc {

int TraversalUnit::spans(const PrimitiveSetup& s, int y, int xlo, int xhi, Span out[2]) {
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

bool TraversalUnit::nextRow() {
  const std::vector<RowSpans>& rows = trace_.rows[std::size_t(prim_)];
  if (row_ >= rows.size()) return false;
  const RowSpans& r = rows[row_++];
  y_ = r.y;
  nSpans_ = r.n;
  rowSpans_[0] = r.s[0];
  rowSpans_[1] = r.s[1];
  span_ = 0;
  x_ = rowSpans_[0].x0;
  return true;
}

bool TraversalUnit::tick(std::uint64_t now) {
  (void)now;
  bool changed = false;
  if (prim_ < 0 && !in_.empty()) {
    prim_ = in_.front();
    in_.pop();
    countItem();
    changed = true;
    const PrimitiveSetup& s = setups_[std::size_t(prim_)];
    row_ = 0;
    k_ = 0;
    if (!s.visible || !nextRow()) prim_ = -1;
    countBusy();
    return changed;  // the first pixels leave next cycle (span solve)
  }
  if (prim_ < 0) {
    countIdle();
    return changed;
  }
  // Issue up to one pixel per pipeline, in span order, stopping at the first pipeline
  // whose FIFO is full (pixels stay in order).
  const int P = int(out_.size());
  std::uint64_t used = 0;  // pipelines already fed this cycle (P <= 64)
  bool stalled = false;
  while (prim_ >= 0) {
    const int p = pipelineOf(x_, y_, P);
    if (used & (std::uint64_t(1) << p)) break;
    if (!out_[std::size_t(p)].canPush()) {
      stalled = true;
      break;
    }
    out_[std::size_t(p)].push({prim_, x_, y_, k_++});
    used |= std::uint64_t(1) << p;
    changed = true;
    if (++x_ >= rowSpans_[span_].x1) {
      if (++span_ < nSpans_) {
        x_ = rowSpans_[span_].x0;
      } else {
        if (!nextRow()) prim_ = -1;
        break;  // a new row starts next cycle
      }
    }
  }
  if (changed) countBusy();
  else if (stalled) countStall();
  else countIdle();
  return changed;
}

}  // namespace qacc
