#include "modeling/splines/height_field_bound.h"

#include <algorithm>
#include <cmath>
#include <limits>
#include <map>

namespace qacc {
namespace {

using Vec = Eigen::Vector2d;

double cross(const Vec& a, const Vec& b) { return a.x() * b.y() - a.y() * b.x(); }

double pointSegment(const Vec& p, const Vec& a, const Vec& b) {
  const Vec d = b - a;
  const double l2 = d.squaredNorm();
  const double t = l2 > 0 ? std::clamp((p - a).dot(d) / l2, 0.0, 1.0) : 0.0;
  return (a + t * d - p).norm();
}

// Distance between two closed segments (0 when they meet).
double segmentSegment(const Vec& a, const Vec& b, const Vec& c, const Vec& d) {
  const double d1 = cross(b - a, c - a), d2 = cross(b - a, d - a);
  const double d3 = cross(d - c, a - c), d4 = cross(d - c, b - c);
  if (((d1 < 0 && d2 > 0) || (d1 > 0 && d2 < 0)) && ((d3 < 0 && d4 > 0) || (d3 > 0 && d4 < 0))) return 0.0;
  return std::min({pointSegment(a, c, d), pointSegment(b, c, d), pointSegment(c, a, b), pointSegment(d, a, b)});
}

// Whether p lies in the closed convex polygon (either orientation).
bool inPolygon(const std::vector<Vec>& poly, const Vec& p) {
  bool neg = false, pos = false;
  for (std::size_t i = 0; i < poly.size(); ++i) {
    const double s = cross(poly[(i + 1) % poly.size()] - poly[i], p - poly[i]);
    neg = neg || s < 0;
    pos = pos || s > 0;
  }
  return !(neg && pos);
}

}  // namespace

HeightFieldBound::HeightFieldBound(const SimplexSplineBase<2>& spline) : spline_(spline), reach_(spline.knotReach()) {
  // Boundary edges: those of exactly one triangle.
  std::map<std::pair<int, int>, int> uses;
  for (const auto& t : spline.simplices())
    for (int e = 0; e < 3; ++e) {
      const int a = t[std::size_t(e)], b = t[std::size_t(e + 1) % 3];
      ++uses[{std::min(a, b), std::max(a, b)}];
    }
  for (const auto& [edge, n] : uses)
    if (n == 1)
      boundary_.push_back({spline.vertices()[std::size_t(edge.first)], spline.vertices()[std::size_t(edge.second)]});
}

bool HeightFieldBound::farFromBoundary(const std::vector<Vec>& polygon) const {
  double size = 0;
  for (const Vec& p : polygon) size = std::max(size, p.cwiseAbs().maxCoeff());
  const double need = reach_ * (1 + 1e-9) + 1e-12 * size;
  for (const auto& e : boundary_) {
    if (inPolygon(polygon, e[0])) return false;
    for (std::size_t i = 0; i < polygon.size(); ++i)
      if (segmentSegment(polygon[i], polygon[(i + 1) % polygon.size()], e[0], e[1]) <= need) return false;
  }
  return true;
}

HeightFieldBound::Range HeightFieldBound::over(const std::vector<Vec>& polygon) const {
  Eigen::AlignedBox2d box;
  for (const Vec& p : polygon) box.extend(p);
  const std::vector<std::size_t> near = spline_.basisNear(box);
  const auto& basis = spline_.basisFunctions();
  Range r;
  r.lo = std::numeric_limits<double>::infinity();
  r.hi = -r.lo;
  if (farFromBoundary(polygon)) {
    // A convex combination of the coefficients of the functions that may be non-zero here.
    r.convexHull = true;
    for (std::size_t i : near) {
      const double c = spline_.coefficientOf(basis[i]);
      r.lo = std::min(r.lo, c);
      r.hi = std::max(r.hi, c);
    }
  } else {
    r.lo = r.hi = 0;
    const int n = spline_.degree();
    for (std::size_t i : near) {
      const auto& B = basis[i];
      const double c = spline_.coefficientOf(B);
      if (c == 0.0) continue;
      for (std::size_t l = 0; l < B.leaves.size(); ++l) {
        const auto& leaf = B.leaves[l];
        // A leaf whose simplex lies strictly outside the polygon adds nothing there.
        bool misses = false;
        for (const auto& f : leaf.bary) {
          double most = -std::numeric_limits<double>::infinity();
          for (const Vec& p : polygon) most = std::max(most, f.at(p));
          misses = misses || most < 0;
        }
        if (misses) continue;
        double lo = c * leaf.weight, hi = lo;
        for (int k = 0; k < n; ++k) {
          const auto& f = B.factors[l * std::size_t(n) + std::size_t(k)];
          double a = std::numeric_limits<double>::infinity(), b = -a;
          for (const Vec& p : polygon) {
            a = std::min(a, f.at(p));
            b = std::max(b, f.at(p));
          }
          const double q[4] = {lo * a, lo * b, hi * a, hi * b};
          lo = *std::min_element(q, q + 4);
          hi = *std::max_element(q, q + 4);
        }
        // Where the polygon leaves the leaf's simplex, the leaf adds 0.
        r.lo += std::min(lo, 0.0);
        r.hi += std::max(hi, 0.0);
      }
    }
  }
  if (!(r.lo <= r.hi)) r.lo = r.hi = 0;  // no basis function reaches the polygon: F = 0
  const double pad = 1e-6 * std::max(std::fabs(r.lo), std::fabs(r.hi));
  r.lo -= pad;
  r.hi += pad;
  return r;
}

}  // namespace qacc
