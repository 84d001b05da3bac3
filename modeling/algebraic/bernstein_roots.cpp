#include "modeling/algebraic/bernstein_roots.h"

#include <algorithm>
#include <cmath>

namespace qacc {

std::vector<double> powerToBernstein(const std::vector<double>& a) {
  const std::size_t n = a.empty() ? 0 : a.size() - 1;
  // binom[i][j] = C(i, j)
  std::vector<std::vector<double>> C(n + 1, std::vector<double>(n + 1, 0.0));
  for (std::size_t i = 0; i <= n; ++i) {
    C[i][0] = 1.0;
    for (std::size_t j = 1; j <= i; ++j) C[i][j] = C[i - 1][j - 1] + (j < i ? C[i - 1][j] : 0.0);
  }
  std::vector<double> b(n + 1, 0.0);
  for (std::size_t i = 0; i <= n; ++i)
    for (std::size_t j = 0; j <= i; ++j) b[i] += C[i][j] / C[n][j] * a[j];
  return b;
}

double evalBernstein(const std::vector<double>& b, double s) {
  std::vector<double> w = b;
  for (std::size_t r = w.size(); r > 1; --r)
    for (std::size_t i = 0; i + 1 < r; ++i) w[i] = (1.0 - s) * w[i] + s * w[i + 1];
  return w.empty() ? 0.0 : w[0];
}

namespace {

struct Search {
  double ztol;
  double min_width;
  bool first_only;
  std::vector<double> roots;
};

void split(const std::vector<double>& b, std::vector<double>& left, std::vector<double>& right) {
  const std::size_t n = b.size();
  std::vector<double> w = b;
  left.resize(n);
  right.resize(n);
  left[0] = w[0];
  right[n - 1] = w[n - 1];
  for (std::size_t r = 1; r < n; ++r) {
    for (std::size_t i = 0; i + r < n; ++i) w[i] = 0.5 * (w[i] + w[i + 1]);
    left[r] = w[0];
    right[n - 1 - r] = w[n - 1 - r];
  }
}

double bisect(const std::vector<double>& b) {
  double lo = 0.0, hi = 1.0;
  const bool rising = b.front() < 0.0;
  for (int it = 0; it < 200 && hi - lo > 1e-16; ++it) {
    const double mid = 0.5 * (lo + hi);
    if (mid <= lo || mid >= hi) break;
    const double v = evalBernstein(b, mid);
    if (v == 0.0) return mid;
    if ((v < 0.0) == rising)
      lo = mid;
    else
      hi = mid;
  }
  return 0.5 * (lo + hi);
}

void search(const std::vector<double>& b, double lo, double hi, Search& s) {
  if (s.first_only && !s.roots.empty()) return;
  bool allPos = true, allNeg = true;
  for (double c : b) {
    allPos = allPos && c > s.ztol;
    allNeg = allNeg && c < -s.ztol;
  }
  if (allPos || allNeg) return;
  // A root exactly at the left end (e.g. on a subdivision point): report it, then look for
  // the others inside.
  if (std::fabs(b.front()) <= s.ztol && (s.roots.empty() || s.roots.back() != lo)) {
    s.roots.push_back(lo);
    if (s.first_only) return;
  }
  // Exactly one sign variation and clearly non-zero ends: exactly one simple root.
  int variations = 0;
  double last = 0.0;
  for (double c : b) {
    if (c == 0.0) continue;
    if (last != 0.0 && (c < 0.0) != (last < 0.0)) ++variations;
    last = c;
  }
  if (variations == 1 && std::fabs(b.front()) > s.ztol && std::fabs(b.back()) > s.ztol) {
    s.roots.push_back(lo + (hi - lo) * bisect(b));
    return;
  }
  bool allSmall = true;
  for (double c : b) allSmall = allSmall && std::fabs(c) <= s.ztol;
  if (allSmall || hi - lo <= s.min_width) {  // zero within tolerance on the whole interval
    s.roots.push_back(0.5 * (lo + hi));
    return;
  }
  std::vector<double> l, r;
  split(b, l, r);
  const double mid = 0.5 * (lo + hi);
  search(l, lo, mid, s);
  search(r, mid, hi, s);
}

Search run(const std::vector<double>& b, const RootOptions& opt, bool first_only) {
  double scale = 0.0;
  for (double c : b) scale = std::max(scale, std::fabs(c));
  Search s{opt.zero_tol * scale, opt.min_width, first_only, {}};
  if (b.empty() || scale == 0.0 || !std::isfinite(scale)) return s;  // zero polynomial: no isolated roots
  search(b, 0.0, 1.0, s);
  if (std::fabs(b.back()) <= s.ztol && (s.roots.empty() || s.roots.back() < 1.0)) s.roots.push_back(1.0);
  return s;
}

}  // namespace

bool firstBernsteinRoot(const std::vector<double>& b, double& root, const RootOptions& opt) {
  Search s = run(b, opt, true);
  if (s.roots.empty()) return false;
  root = s.roots.front();
  return true;
}

std::vector<double> allBernsteinRoots(const std::vector<double>& b, const RootOptions& opt) {
  Search s = run(b, opt, false);
  std::vector<double> out;
  for (double r : s.roots)
    if (out.empty() || r - out.back() > 1e-5) out.push_back(r);
  return out;
}

}  // namespace qacc
