#include "modeling/splines/height_field_bound.h"

#include <algorithm>
#include <array>
#include <cmath>
#include <limits>

namespace qacc {
namespace {

using Vec = Eigen::Vector2d;
using Polygon = std::vector<Vec>;
using Affine = SimplexSplineBase<2>::Affine;

// The part of the convex polygon where f >= -slack (Sutherland-Hodgman, one edge).
void clipAbove(const Polygon& in, const Affine& f, double slack, Polygon& out) {
  out.clear();
  const std::size_t n = in.size();
  for (std::size_t i = 0; i < n; ++i) {
    const Vec& a = in[i];
    const Vec& b = in[(i + 1) % n];
    const double fa = f.at(a) + slack, fb = f.at(b) + slack;
    if (fa >= 0) out.push_back(a);
    if ((fa < 0 && fb > 0) || (fa > 0 && fb < 0)) out.push_back(a + (b - a) * (fa / (fa - fb)));
  }
}

// q(x, y) = xx x² + xy x y + yy y² + x x + y y + c, with its exact range over a convex polygon.
struct Quadratic {
  double xx = 0, xy = 0, yy = 0, x = 0, y = 0, c = 0;
  static Quadratic constant(double w) {
    Quadratic q;
    q.c = w;
    return q;
  }
  static Quadratic affine(const Affine& f, double w) {
    Quadratic q;
    q.x = w * f.a.x();
    q.y = w * f.a.y();
    q.c = w * f.b;
    return q;
  }
  static Quadratic product(const Affine& f, const Affine& g, double w) {
    Quadratic q;
    q.xx = w * f.a.x() * g.a.x();
    q.yy = w * f.a.y() * g.a.y();
    q.xy = w * (f.a.x() * g.a.y() + f.a.y() * g.a.x());
    q.x = w * (f.a.x() * g.b + f.b * g.a.x());
    q.y = w * (f.a.y() * g.b + f.b * g.a.y());
    q.c = w * f.b * g.b;
    return q;
  }
  void add(const Quadratic& o) {
    xx += o.xx, xy += o.xy, yy += o.yy, x += o.x, y += o.y, c += o.c;
  }
  double at(const Vec& p) const {
    return (xx * p.x() + xy * p.y() + x) * p.x() + (yy * p.y() + y) * p.y() + c;
  }
  // The sum of its terms' magnitudes at the polygon's farthest corner (rounding's scale).
  double magnitude(const Polygon& poly) const {
    double m = 0;
    for (const Vec& p : poly) {
      const double ax = std::fabs(p.x()), ay = std::fabs(p.y());
      m = std::max(m, std::fabs(xx) * ax * ax + std::fabs(xy) * ax * ay + std::fabs(yy) * ay * ay +
                          std::fabs(x) * ax + std::fabs(y) * ay + std::fabs(c));
    }
    return m;
  }
  // The least and greatest values over the convex polygon: at a corner, at the extremum along
  // an edge, or at the stationary point inside.
  void range(const Polygon& poly, double& lo, double& hi) const {
    lo = std::numeric_limits<double>::infinity();
    hi = -lo;
    auto take = [&](const Vec& p) {
      const double v = at(p);
      lo = std::min(lo, v);
      hi = std::max(hi, v);
    };
    const std::size_t n = poly.size();
    for (std::size_t i = 0; i < n; ++i) {
      const Vec& p = poly[i];
      const Vec d = poly[(i + 1) % n] - p;
      take(p);
      // Along the edge: q(p + t d) = α t² + β t + γ.
      const double alpha = xx * d.x() * d.x() + xy * d.x() * d.y() + yy * d.y() * d.y();
      const double beta = (2 * xx * p.x() + xy * p.y() + x) * d.x() + (2 * yy * p.y() + xy * p.x() + y) * d.y();
      if (alpha != 0) {
        const double t = -beta / (2 * alpha);
        if (t > 0 && t < 1) take(p + t * d);
      }
    }
    if (n >= 3) {
      // ∇q = 0: [2xx xy; xy 2yy] u = -(x, y).
      const double det = 4 * xx * yy - xy * xy;
      if (det != 0) {
        const Vec u((-x * 2 * yy + xy * y) / det, (-2 * xx * y + xy * x) / det);
        bool neg = false, pos = false;
        for (std::size_t i = 0; i < n; ++i) {
          const Vec e = poly[(i + 1) % n] - poly[i], w = u - poly[i];
          const double s = e.x() * w.y() - e.y() * w.x();
          neg = neg || s < 0;
          pos = pos || s > 0;
        }
        if (!(neg && pos) && std::isfinite(u.x()) && std::isfinite(u.y())) take(u);
      }
    }
    if (n == 0) lo = hi = 0;
  }
};

// The two closed halves of the convex polygon on either side of the line x[axis] = at.
void halve(const Polygon& p, int axis, double at, Polygon& below, Polygon& above) {
  Affine f;
  f.a = Vec::Zero();
  f.a[axis] = -1;
  f.b = at;
  clipAbove(p, f, 0.0, below);
  f.a[axis] = 1;
  f.b = -at;
  clipAbove(p, f, 0.0, above);
}

}  // namespace

HeightFieldBound::Range HeightFieldBound::over(const Polygon& polygon) const { return over(polygon, nullptr); }

HeightFieldBound::Range HeightFieldBound::over(const Polygon& polygon, Straddle* straddle) const {
  Eigen::AlignedBox2d box;
  for (const Vec& p : polygon) box.extend(p);
  const auto& basis = spline_.basisFunctions();
  const int n = spline_.degree();
  // Rounding's reach in the barycentric forms: their values are O(1) over the knot simplex,
  // computed with relative errors of about 1e-15 of the coordinates' magnitude.
  const double scale = std::max({1.0, box.min().cwiseAbs().maxCoeff(), box.max().cwiseAbs().maxCoeff()});
  // The leaves near the polygon, grouped by knot simplex: F = Σ_S 1_S T_S.
  struct Item {
    std::array<int, 3> key;
    std::size_t basis, leaf;
  };
  std::vector<Item> items;
  for (std::size_t i : spline_.basisNear(box)) {
    if (spline_.coefficientOf(basis[i]) == 0.0) continue;
    for (std::size_t l = 0; l < basis[i].leaves.size(); ++l) {
      Item it{basis[i].leaves[l].knots, i, l};
      std::sort(it.key.begin(), it.key.end());
      items.push_back(it);
    }
  }
  std::sort(items.begin(), items.end(), [](const Item& a, const Item& b) {
    return a.key != b.key ? a.key < b.key : a.basis != b.basis ? a.basis < b.basis : a.leaf < b.leaf;
  });
  Quadratic held;  // Σ T_S over the simplices whose closed hull holds the polygon
  double lo = 0, hi = 0, magnitude = 0, widest = 0;
  Polygon clipped, scratch;
  for (std::size_t first = 0; first < items.size();) {
    std::size_t last = first;
    while (last < items.size() && items[last].key == items[first].key) ++last;
    const auto& simplex = basis[items[first].basis].leaves[items[first].leaf].bary;
    // The polygon within the simplex's closed hull (widened by rounding's reach), whether the
    // closed simplex holds it all (up to that reach), and a side that crosses it.
    clipped = polygon;
    bool holdsAll = true;
    const Affine* side = nullptr;
    for (const Affine& f : simplex) {
      const double slack = 1e-9 * scale * std::max(1.0, f.a.norm());
      double least = std::numeric_limits<double>::infinity(), most = -least;
      for (const Vec& p : polygon) {
        least = std::min(least, f.at(p));
        most = std::max(most, f.at(p));
      }
      holdsAll = holdsAll && least >= -slack;
      if (least < -slack && most > slack) side = &f;
      if (!clipped.empty()) {
        clipAbove(clipped, f, slack, scratch);
        clipped.swap(scratch);
      }
    }
    if (clipped.empty()) {  // the simplex misses the polygon
      first = last;
      continue;
    }
    if (n <= 2) {
      // T_S as one quadratic.
      Quadratic t;
      for (std::size_t k = first; k < last; ++k) {
        const auto& B = basis[items[k].basis];
        const std::size_t l = items[k].leaf;
        const double w = spline_.coefficientOf(B) * B.leaves[l].weight;
        if (n == 0) t.add(Quadratic::constant(w));
        if (n == 1) t.add(Quadratic::affine(B.factors[l], w));
        if (n == 2) t.add(Quadratic::product(B.factors[2 * l], B.factors[2 * l + 1], w));
      }
      magnitude += t.magnitude(clipped);
      if (holdsAll) {
        held.add(t);
      } else {
        double a = 0, b = 0;
        t.range(clipped, a, b);
        const double widening = std::max(a, 0.0) - std::min(b, 0.0);
        if (side && straddle && widening > widest) {
          widest = widening;
          straddle->line = *side;
          straddle->found = true;
        }
        lo += std::min(a, 0.0);
        hi += std::max(b, 0.0);
      }
    } else {
      // Degree 3 and 4: each leaf's product of intervals (the factors are affine, so each lies
      // between its values at the clipped polygon's corners).
      for (std::size_t k = first; k < last; ++k) {
        const auto& B = basis[items[k].basis];
        const std::size_t l = items[k].leaf;
        double a = spline_.coefficientOf(B) * B.leaves[l].weight, b = a;
        for (int j = 0; j < n; ++j) {
          const Affine& f = B.factors[l * std::size_t(n) + std::size_t(j)];
          double fl = std::numeric_limits<double>::infinity(), fh = -fl;
          for (const Vec& p : clipped) {
            fl = std::min(fl, f.at(p));
            fh = std::max(fh, f.at(p));
          }
          const double q[4] = {a * fl, a * fh, b * fl, b * fh};
          a = *std::min_element(q, q + 4);
          b = *std::max_element(q, q + 4);
        }
        magnitude += std::max(std::fabs(a), std::fabs(b));
        lo += holdsAll ? a : std::min(a, 0.0);
        hi += holdsAll ? b : std::max(b, 0.0);
      }
    }
    first = last;
  }
  if (n <= 2) {
    double a = 0, b = 0;
    held.range(polygon, a, b);
    magnitude += held.magnitude(polygon);
    lo += a;
    hi += b;
  }
  const double pad = 1e-6 * magnitude;
  return {lo - pad, hi + pad};
}

bool HeightFieldBound::mayReach(const Polygon& polygon, const ViewVolume& view, int depth) const {
  if (polygon.size() < 3) return true;
  // A point of the surface itself in the view: the polygon is kept.
  Vec centre = Vec::Zero();
  for (const Vec& p : polygon) centre += p / double(polygon.size());
  const Eigen::Vector3d onSurface(centre.x(), centre.y(), spline_.eval(centre));
  if (view.mayContain(&onSurface, 1)) return true;
  Straddle straddle;
  const Range z = over(polygon, &straddle);
  std::vector<Eigen::Vector3d> prism;
  for (const Vec& v : polygon) {
    prism.emplace_back(v.x(), v.y(), z.lo);
    prism.emplace_back(v.x(), v.y(), z.hi);
  }
  if (!view.mayContain(prism)) return false;
  if (depth == 0) return true;
  Polygon below, above;
  if (straddle.found) {
    // Cut along the side of the leaf simplex that widened the range most: on each side the
    // leaf is either wholly present or absent.
    Affine f = straddle.line;
    clipAbove(polygon, f, 0.0, above);
    f.a = -f.a;
    f.b = -f.b;
    clipAbove(polygon, f, 0.0, below);
  } else {
    Eigen::AlignedBox2d box;
    for (const Vec& p : polygon) box.extend(p);
    int axis = 0;
    box.sizes().maxCoeff(&axis);
    halve(polygon, axis, box.center()[axis], below, above);
  }
  // The closed halves cover the polygon; a degenerate one (rounding) is not halved further.
  if (below.size() < 3 || above.size() < 3) return true;
  return mayReach(below, view, depth - 1) || mayReach(above, view, depth - 1);
}

}  // namespace qacc
