#include "modeling/splines/simplex_spline2.h"

#include <algorithm>
#include <cmath>
#include <optional>
#include <set>

#include "modeling/splines/height_field_bound.h"

namespace qacc {
namespace {

using Vec = Eigen::Vector2d;

double det3(const Vec& a, const Vec& b, const Vec& c) {  // d(a, b, c) = twice the signed area
  return (b - a).x() * (c - a).y() - (b - a).y() * (c - a).x();
}

// A vertical clip plane through the line of p, q: canonical coefficients from the points in
// lexicographic order, so every cell cut by the same line gets bit-identical (or exactly
// opposite) half-spaces.
Eigen::Vector4d canonicalLine(Vec p, Vec q) {
  if (q.x() < p.x() || (q.x() == p.x() && q.y() < p.y())) std::swap(p, q);
  const Vec n(q.y() - p.y(), p.x() - q.x());
  return Eigen::Vector4d(n.x(), n.y(), 0.0, -n.dot(p));
}

double lineEval(const Eigen::Vector4d& h, const Vec& u) { return h.x() * u.x() + h.y() * u.y() + h.w(); }

struct WorkCell {
  std::vector<Vec> poly;  // convex, counter-clockwise
  std::vector<HalfSpace> clip;
};

// Splits `c` by the line h (value <= 0 side gets h, the other side h.opposite()).
bool splitCell(const WorkCell& c, const Eigen::Vector4d& h, double eps, WorkCell& neg, WorkCell& pos) {
  const std::size_t n = c.poly.size();
  std::vector<double> v(n);
  bool anyNeg = false, anyPos = false;
  for (std::size_t i = 0; i < n; ++i) {
    v[i] = lineEval(h, c.poly[i]);
    anyNeg = anyNeg || v[i] < -eps;
    anyPos = anyPos || v[i] > eps;
  }
  if (!anyNeg || !anyPos) return false;
  neg.poly.clear();
  pos.poly.clear();
  for (std::size_t i = 0; i < n; ++i) {
    const std::size_t j = (i + 1) % n;
    const double a = std::fabs(v[i]) <= eps ? 0.0 : v[i];
    const double b = std::fabs(v[j]) <= eps ? 0.0 : v[j];
    if (a <= 0) neg.poly.push_back(c.poly[i]);
    if (a >= 0) pos.poly.push_back(c.poly[i]);
    if ((a < 0 && b > 0) || (a > 0 && b < 0)) {
      const Vec x = c.poly[i] + (c.poly[j] - c.poly[i]) * (v[i] / (v[i] - v[j]));
      neg.poly.push_back(x);
      pos.poly.push_back(x);
    }
  }
  const HalfSpace hs(h);
  neg.clip = c.clip;
  neg.clip.push_back(hs);
  pos.clip = c.clip;
  pos.clip.push_back(hs.opposite());
  return neg.poly.size() >= 3 && pos.poly.size() >= 3;
}

// Does the open segment pq cross the interior of the convex polygon?
bool segmentCrosses(const WorkCell& c, const Vec& p, const Vec& q, double eps) {
  double t0 = 0, t1 = 1;
  const std::size_t n = c.poly.size();
  for (std::size_t i = 0; i < n; ++i) {
    const Vec& a = c.poly[i];
    const Vec& b = c.poly[(i + 1) % n];
    // inside (ccw): cross(b - a, u - a) > 0
    const Vec e = b - a;
    const double fp = e.x() * (p - a).y() - e.y() * (p - a).x();
    const double fq = e.x() * (q - a).y() - e.y() * (q - a).x();
    const double len = e.norm();
    if (fp <= eps * len && fq <= eps * len) return false;
    if (fp < 0 || fq < 0) {
      const double t = fp / (fp - fq);
      if (fp < 0)
        t0 = std::max(t0, t);
      else
        t1 = std::min(t1, t);
    }
  }
  return t1 - t0 > 1e-9;
}

}  // namespace

std::vector<SimplexSpline2::Cell> SimplexSpline2::cells(const ViewVolume* view, ViewCullCount* count) const {
  // Segments between knots that occur together in a knot set.
  std::set<std::array<double, 4>> segs;
  const auto betas = multiIndices(n_);
  double scale = 0;
  for (const Vec& v : verts_)
    for (const Vec& w : verts_) scale = std::max(scale, (v - w).norm());
  const double eps = 1e-12 * std::max(scale, 1e-300) * std::max(scale, 1e-300);
  for (std::size_t t = 0; t < simplices_.size(); ++t)
    for (const auto& b : betas) {
      const auto V = knotSet(t, b);
      for (std::size_t i = 0; i < V.size(); ++i)
        for (std::size_t j = i + 1; j < V.size(); ++j) {
          if ((V[i] - V[j]).norm() <= 1e-12 * scale) continue;
          Vec p = V[i], q = V[j];
          if (q.x() < p.x() || (q.x() == p.x() && q.y() < p.y())) std::swap(p, q);
          segs.insert({p.x(), p.y(), q.x(), q.y()});
        }
    }
  // Start from the triangles of the triangulation (their edges are knot segments too).
  std::vector<WorkCell> work;
  for (const auto& t : simplices_) {
    WorkCell c;
    Vec a = verts_[std::size_t(t[0])], b = verts_[std::size_t(t[1])], d = verts_[std::size_t(t[2])];
    if (det3(a, b, d) < 0) std::swap(b, d);
    c.poly = {a, b, d};
    const Vec centre = (a + b + d) / 3.0;
    for (int e = 0; e < 3; ++e) {
      const Eigen::Vector4d h = canonicalLine(c.poly[std::size_t(e)], c.poly[std::size_t(e + 1) % 3]);
      c.clip.push_back(lineEval(h, centre) < 0 ? HalfSpace(h) : HalfSpace(h).opposite());
    }
    if (!domain_.isEmpty()) {
      // Clip to the domain rectangle: x >= xmin, x <= xmax, y >= ymin, y <= ymax.
      const Eigen::Vector4d lines[4] = {{-1, 0, 0, domain_.min().x()}, {1, 0, 0, -domain_.max().x()},
                                        {0, -1, 0, domain_.min().y()}, {0, 1, 0, -domain_.max().y()}};
      bool empty = false;
      for (const auto& h : lines) {
        bool out = true, in = true;
        for (const Vec& v : c.poly) {
          out = out && lineEval(h, v) >= -eps;
          in = in && lineEval(h, v) <= eps;
        }
        if (out) {
          empty = true;
          break;
        }
        if (in) continue;
        WorkCell a, b;
        if (splitCell(c, h, eps, a, b)) {
          a.clip.back() = HalfSpace(h);
          c = a;
        }
      }
      if (empty) continue;
    }
    work.push_back(std::move(c));
  }
  // Split every cell by every segment that crosses it, segment by segment in the set's order.
  // A cell lies inside one triangle and a segment can cross only the triangles its box meets,
  // so each triangle is split on its own by the segments of the grid buckets its box meets —
  // in the same order, which gives the same cells in the same order as splitting the whole
  // list by every segment, in time linear in the triangles instead of their product with the
  // segments (n 64 with G1 knots ran for minutes).
  std::vector<std::array<double, 4>> segList(segs.begin(), segs.end());
  Eigen::AlignedBox2d all;
  for (const WorkCell& c : work)
    for (const Vec& v : c.poly) all.extend(v);
  // Far beyond the crossing test's tolerance (a distance of eps):
  const double margin = std::max(1e-6 * std::max(scale, 1e-300), 10 * eps);
  const int G = std::max(1, int(std::sqrt(double(work.size()))));
  const Vec lo = all.isEmpty() ? Vec::Zero() : Vec(all.min() - Vec::Constant(margin));
  const Vec size = all.isEmpty() ? Vec::Ones() : Vec(all.sizes() + Vec::Constant(2 * margin));
  // Clamped before the conversion to int: with coordinates near 1e300 the quotient is out of
  // int's range or not a number (a conversion of either is undefined behaviour).
  auto bucket = [&](double v, int axis) {
    const double t = std::floor((v - lo[axis]) / size[axis] * G);
    if (!(t >= 0)) return 0;
    return t >= double(G - 1) ? G - 1 : int(t);
  };
  std::vector<std::vector<std::size_t>> buckets(std::size_t(G) * std::size_t(G));
  for (std::size_t k = 0; k < segList.size(); ++k) {
    const auto& sg = segList[k];
    const int x0 = bucket(std::min(sg[0], sg[2]) - margin, 0), x1 = bucket(std::max(sg[0], sg[2]) + margin, 0);
    const int y0 = bucket(std::min(sg[1], sg[3]) - margin, 1), y1 = bucket(std::max(sg[1], sg[3]) + margin, 1);
    for (int y = y0; y <= y1; ++y)
      for (int x = x0; x <= x1; ++x) buckets[std::size_t(y) * std::size_t(G) + std::size_t(x)].push_back(k);
  }
  std::vector<WorkCell> split;
  split.reserve(work.size() * 4);
  std::vector<std::size_t> near;
  std::optional<HeightFieldBound> bound;
  if (view) bound.emplace(*this);
  for (const WorkCell& triangle : work) {
    if (view) {
      // The prisms of the triangle (or of its pieces) over safe ranges of F hold its surface
      // (height_field_bound.h).
      const bool mayBeSeen = bound->mayReach(triangle.poly, *view);
      if (count) count->keep(mayBeSeen);
      if (!mayBeSeen) continue;
    }
    Eigen::AlignedBox2d box;
    for (const Vec& v : triangle.poly) box.extend(v);
    near.clear();
    for (int y = bucket(box.min().y() - margin, 1); y <= bucket(box.max().y() + margin, 1); ++y)
      for (int x = bucket(box.min().x() - margin, 0); x <= bucket(box.max().x() + margin, 0); ++x)
        for (std::size_t k : buckets[std::size_t(y) * std::size_t(G) + std::size_t(x)]) near.push_back(k);
    std::sort(near.begin(), near.end());
    near.erase(std::unique(near.begin(), near.end()), near.end());
    std::vector<WorkCell> cellsOfTriangle{triangle};
    for (std::size_t k : near) {
      const auto& sg = segList[k];
      const Vec p(sg[0], sg[1]), q(sg[2], sg[3]);
      const Eigen::Vector4d h = canonicalLine(p, q);
      const double heps = eps / std::max(1e-300, std::hypot(h.x(), h.y()));
      std::vector<WorkCell> next;
      next.reserve(cellsOfTriangle.size() + 1);
      for (const WorkCell& c : cellsOfTriangle) {
        WorkCell a, b;
        if (segmentCrosses(c, p, q, eps) && splitCell(c, h, heps * std::hypot(h.x(), h.y()), a, b)) {
          next.push_back(std::move(a));
          next.push_back(std::move(b));
        } else {
          next.push_back(c);
        }
      }
      cellsOfTriangle.swap(next);
    }
    for (WorkCell& c : cellsOfTriangle) split.push_back(std::move(c));
  }
  work.swap(split);
  std::vector<Cell> out;
  out.reserve(work.size());
  for (WorkCell& c : work) {
    Cell cell;
    cell.polygon = c.poly;
    // Keep only the half-spaces that carry an edge of the final polygon.
    for (const HalfSpace& h : c.clip) {
      const double hn = std::hypot(h.p.x(), h.p.y());
      int on = 0;
      for (const Vec& v : c.poly) on += std::fabs(lineEval(h.p, v)) <= 1e-9 * scale * hn;
      if (on >= 2) cell.edges.push_back(h);
    }
    Vec centre = Vec::Zero();
    for (const Vec& v : c.poly) centre += v / double(c.poly.size());
    cell.poly = localPolynomial(centre);
    out.push_back(std::move(cell));
  }
  return out;
}

std::vector<Primitive> SimplexSpline2::toPrimitives(int material, int object, const ViewVolume* view,
                                                    ViewCullCount* count) const {
  std::vector<Primitive> out;
  for (const Cell& c : cells(view, count)) {
    const Polynomial3& p = c.poly;
    // f = z - p(x, y): interior (f <= 0) below the height field.
    Primitive prim;
    prim.quadric = Quadric::fromCoefficients(-p.coefficient(2, 0, 0), -p.coefficient(0, 2, 0), 0.0,
                                             -0.5 * p.coefficient(1, 1, 0), 0.0, 0.0, -0.5 * p.coefficient(1, 0, 0),
                                             -0.5 * p.coefficient(0, 1, 0), 0.5, -p.coefficient(0, 0, 0));
    prim.clip = c.edges;
    prim.material = material;
    prim.object = object;
    out.push_back(std::move(prim));
  }
  return out;
}

}  // namespace qacc
