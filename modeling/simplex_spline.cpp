#include "modeling/simplex_spline.h"

#include <algorithm>
#include <cmath>
#include <limits>
#include <map>
#include <set>
#include <stdexcept>
#include <string>
#include <type_traits>

namespace qacc {
namespace {

using Vec = Eigen::Vector2d;

// Fixed generic direction of the half-open rule.
const Vec kTieDirection(1.0, 0.3183098861837907);

double det3(const Vec& a, const Vec& b, const Vec& c) {  // d(a, b, c) = twice the signed area
  return (b - a).x() * (c - a).y() - (b - a).y() * (c - a).x();
}

// Barycentric coordinates in (p0, p1, p2) as affine functions λ_j(u) = a_j · u + b_j.
struct Affine {
  Vec a;
  double b;
  double at(const Vec& u) const { return a.dot(u) + b; }
};

void barycentricForms(const Vec& p0, const Vec& p1, const Vec& p2, Affine l[3]) {
  const double d = det3(p0, p1, p2);
  const Vec P[3] = {p0, p1, p2};
  for (int j = 0; j < 3; ++j) {
    const Vec& q = P[(j + 1) % 3];
    const Vec& r = P[(j + 2) % 3];
    // λ_j(u) = d(u, q, r) / d(p_j, q, r) = d(u, q, r) / d.
    // d(u, q, r) = (q - u) x (r - u) = q x r - u x r + u x q  (2D cross products)
    l[j].a = Vec(q.y() - r.y(), r.x() - q.x()) / d;
    l[j].b = (q.x() * r.y() - q.y() * r.x()) / d;
  }
}

double scaleOf(const std::vector<Vec>& V) {
  double s = 0;
  for (const Vec& v : V)
    for (const Vec& w : V) s = std::max(s, (v - w).cwiseAbs().maxCoeff());
  return s;
}

bool degenerate(double d, double scale) { return std::fabs(d) <= 1e-12 * scale * scale; }

// Half-open membership of u in the triangle with barycentric forms l.
bool insideHalfOpen(const Affine l[3], const Vec& u) {
  for (int j = 0; j < 3; ++j) {
    const double v = l[j].at(u);
    if (v > 0) continue;
    if (v == 0 && l[j].a.dot(kTieDirection) > 0) continue;
    return false;
  }
  return true;
}

Polynomial3 affinePoly(const Affine& l) { return Polynomial3::affine(Eigen::Vector3d(l.a.x(), l.a.y(), 0.0), l.b); }

// The recursion with values (T = double) or local polynomials (T = Polynomial3) at `u`.
template <class T>
T simplexM(const std::vector<Vec>& V, const Vec& u, double scale) {
  if (V.size() < 3) return T(0.0);
  // The non-degenerate triple with the largest |d| (stable λ).
  double best = 0;
  int bi = -1, bj = -1, bk = -1;
  for (std::size_t i = 0; i < V.size(); ++i)
    for (std::size_t j = i + 1; j < V.size(); ++j)
      for (std::size_t k = j + 1; k < V.size(); ++k) {
        const double d = std::fabs(det3(V[i], V[j], V[k]));
        if (d > best) {
          best = d;
          bi = int(i);
          bj = int(j);
          bk = int(k);
        }
      }
  if (bi < 0 || degenerate(best, scale)) return T(0.0);  // knots on a line: zero almost everywhere
  Affine l[3];
  barycentricForms(V[std::size_t(bi)], V[std::size_t(bj)], V[std::size_t(bk)], l);
  if (V.size() == 3) return insideHalfOpen(l, u) ? T(1.0 / best) : T(0.0);
  const int idx[3] = {bi, bj, bk};
  T sum(0.0);
  for (int q = 0; q < 3; ++q) {
    std::vector<Vec> W;
    W.reserve(V.size() - 1);
    for (std::size_t m = 0; m < V.size(); ++m)
      if (int(m) != idx[q]) W.push_back(V[m]);
    const T sub = simplexM<T>(W, u, scale);
    if constexpr (std::is_same<T, double>::value)
      sum += l[q].at(u) * sub;
    else
      sum = sum + affinePoly(l[q]) * sub;
  }
  return sum;
}

// Polynomial3 has no constructor from double; give the template one.
struct PolyT : Polynomial3 {
  PolyT(double c) : Polynomial3(Polynomial3::constant(c)) {}  // NOLINT(implicit)
  PolyT(const Polynomial3& p) : Polynomial3(p) {}            // NOLINT(implicit)
};

}  // namespace

SimplexSpline2::SimplexSpline2(int degree, std::vector<Vec> vertices, std::vector<std::array<int, 3>> triangles,
                               std::vector<std::vector<Vec>> knots)
    : n_(degree), verts_(std::move(vertices)), tris_(std::move(triangles)), knots_(std::move(knots)) {
  if (n_ < 0 || n_ > 4) throw std::invalid_argument("SimplexSpline2: degree must be in [0, 4]");
  if (knots_.size() != verts_.size()) throw std::invalid_argument("SimplexSpline2: one knot cloud per vertex");
  for (const auto& k : knots_)
    if (int(k.size()) != n_) throw std::invalid_argument("SimplexSpline2: each knot cloud needs degree extra knots");
  for (const auto& t : tris_) {
    for (int v : t)
      if (v < 0 || v >= int(verts_.size())) throw std::invalid_argument("SimplexSpline2: triangle vertex out of range");
    if (det3(verts_[std::size_t(t[0])], verts_[std::size_t(t[1])], verts_[std::size_t(t[2])]) == 0)
      throw std::invalid_argument("SimplexSpline2: degenerate triangle");
  }
  coef_.assign(tris_.size(), std::vector<double>(multiIndices(n_).size(), 0.0));
}

std::vector<SimplexSpline2::Beta> SimplexSpline2::multiIndices(int n) {
  std::vector<Beta> out;
  for (int i = n; i >= 0; --i)
    for (int j = n - i; j >= 0; --j) out.push_back({i, j, n - i - j});
  return out;
}

std::vector<Vec> SimplexSpline2::knotSet(std::size_t tri, const Beta& b) const {
  std::vector<Vec> V;
  for (int c = 0; c < 3; ++c)
    for (int k = 0; k <= b[std::size_t(c)]; ++k) V.push_back(knot(tris_[tri][std::size_t(c)], k));
  return V;
}

std::vector<Vec> SimplexSpline2::lowerSet(std::size_t tri, const Beta& b) const {
  std::vector<Vec> U;
  for (int c = 0; c < 3; ++c)
    for (int k = 0; k < b[std::size_t(c)]; ++k) U.push_back(knot(tris_[tri][std::size_t(c)], k));
  return U;
}

double SimplexSpline2::basis(std::size_t tri, const Beta& b, const Vec& u) const {
  const auto V = knotSet(tri, b);
  const auto& t = tris_[tri];
  const double d = std::fabs(det3(knot(t[0], b[0]), knot(t[1], b[1]), knot(t[2], b[2])));
  return d * simplexM<double>(V, u, scaleOf(V));
}

double SimplexSpline2::eval(const Vec& u) const {
  const auto betas = multiIndices(n_);
  double s = 0;
  for (std::size_t t = 0; t < tris_.size(); ++t)
    for (std::size_t k = 0; k < betas.size(); ++k)
      if (coef_[t][k] != 0.0) s += coef_[t][k] * basis(t, betas[k], u);
  return s;
}

Polynomial3 SimplexSpline2::localPolynomial(const Vec& probe) const {
  const auto betas = multiIndices(n_);
  Polynomial3 s;
  for (std::size_t t = 0; t < tris_.size(); ++t)
    for (std::size_t k = 0; k < betas.size(); ++k) {
      if (coef_[t][k] == 0.0) continue;
      const auto V = knotSet(t, betas[k]);
      const auto& tr = tris_[t];
      const double d = std::fabs(det3(knot(tr[0], betas[k][0]), knot(tr[1], betas[k][1]), knot(tr[2], betas[k][2])));
      const PolyT m = simplexM<PolyT>(V, probe, scaleOf(V));
      s = s + static_cast<const Polynomial3&>(m) * (coef_[t][k] * d);
    }
  return s;
}

std::vector<std::vector<double>> SimplexSpline2::blossomCoefficients(const Polynomial3& p) const {
  if (n_ > 2) throw std::invalid_argument("blossomCoefficients: implemented for degree <= 2");
  if (p.degree() > n_) throw std::invalid_argument("blossomCoefficients: polynomial degree above the spline degree");
  // p(u) = uᵀ A u + g·u + c; blossom P(a, b) = aᵀ A b + ½ g·(a + b) + c; P(a) = p(a).
  Eigen::Matrix2d A;
  A << p.coefficient(2, 0, 0), 0.5 * p.coefficient(1, 1, 0), 0.5 * p.coefficient(1, 1, 0), p.coefficient(0, 2, 0);
  const Vec g(p.coefficient(1, 0, 0), p.coefficient(0, 1, 0));
  const double c = p.coefficient(0, 0, 0);
  const auto betas = multiIndices(n_);
  std::vector<std::vector<double>> out(tris_.size(), std::vector<double>(betas.size()));
  for (std::size_t t = 0; t < tris_.size(); ++t)
    for (std::size_t k = 0; k < betas.size(); ++k) {
      const auto U = lowerSet(t, betas[k]);
      double v = c;
      if (U.size() == 1) v = p.eval(Eigen::Vector3d(U[0].x(), U[0].y(), 0));
      if (U.size() == 2) v = U[0].dot(A * U[1]) + 0.5 * g.dot(U[0] + U[1]) + c;
      out[t][k] = v;
    }
  return out;
}

std::vector<std::vector<double>> SimplexSpline2::grevilleCoefficients(const Polynomial3& h) const {
  const auto betas = multiIndices(n_);
  std::vector<std::vector<double>> out(tris_.size(), std::vector<double>(betas.size()));
  for (std::size_t t = 0; t < tris_.size(); ++t)
    for (std::size_t k = 0; k < betas.size(); ++k) {
      const auto U = lowerSet(t, betas[k]);
      Vec xi = Vec::Zero();
      if (U.empty()) {
        for (int v : tris_[t]) xi += verts_[std::size_t(v)] / 3.0;
      } else {
        for (const Vec& q : U) xi += q / double(U.size());
      }
      out[t][k] = h.eval(Eigen::Vector3d(xi.x(), xi.y(), 0));
    }
  return out;
}

namespace {

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

std::vector<SimplexSpline2::Cell> SimplexSpline2::cells() const {
  // Segments between knots that occur together in a knot set.
  std::set<std::array<double, 4>> segs;
  const auto betas = multiIndices(n_);
  double scale = 0;
  for (const Vec& v : verts_)
    for (const Vec& w : verts_) scale = std::max(scale, (v - w).norm());
  const double eps = 1e-12 * std::max(scale, 1e-300) * std::max(scale, 1e-300);
  for (std::size_t t = 0; t < tris_.size(); ++t)
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
  for (const auto& t : tris_) {
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
  for (const auto& s : segs) {
    const Vec p(s[0], s[1]), q(s[2], s[3]);
    const Eigen::Vector4d h = canonicalLine(p, q);
    const double heps = eps / std::max(1e-300, std::hypot(h.x(), h.y()));
    std::vector<WorkCell> next;
    next.reserve(work.size());
    for (const WorkCell& c : work) {
      WorkCell a, b;
      if (segmentCrosses(c, p, q, eps) && splitCell(c, h, heps * std::hypot(h.x(), h.y()), a, b)) {
        next.push_back(std::move(a));
        next.push_back(std::move(b));
      } else {
        next.push_back(c);
      }
    }
    work.swap(next);
  }
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

std::vector<Primitive> SimplexSpline2::toPrimitives(int material, int object) const {
  std::vector<Primitive> out;
  for (const Cell& c : cells()) {
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

std::vector<std::vector<Eigen::Vector2d>> knotClouds(const std::vector<Eigen::Vector2d>& vertices,
                                                    const std::vector<std::array<int, 3>>& triangles,
                                                    int degree, bool g1, double radius) {
  std::vector<double> shortest(vertices.size(), std::numeric_limits<double>::infinity());
  for (const auto& t : triangles)
    for (int e = 0; e < 3; ++e) {
      const int a = t[std::size_t(e)], b = t[std::size_t(e + 1) % 3];
      const double l = (vertices[std::size_t(a)] - vertices[std::size_t(b)]).norm();
      shortest[std::size_t(a)] = std::min(shortest[std::size_t(a)], l);
      shortest[std::size_t(b)] = std::min(shortest[std::size_t(b)], l);
    }
  std::vector<std::vector<Eigen::Vector2d>> out(vertices.size());
  for (std::size_t i = 0; i < vertices.size(); ++i)
    for (int k = 1; k <= degree; ++k) {
      if (!g1 || !std::isfinite(shortest[i])) {
        out[i].push_back(vertices[i]);
        continue;
      }
      // Irregular but fixed directions and lengths (golden-ratio sequences).
      const double u = std::fmod(0.6180339887498949 * double(i * 7 + std::size_t(k) * 3 + 1), 1.0);
      const double w = std::fmod(0.7548776662466927 * double(i * 5 + std::size_t(k) * 11 + 2), 1.0);
      const double ang = 6.283185307179586 * u;
      const double r = radius * shortest[i] * (0.55 + 0.45 * w) * (k == 1 ? 1.0 : 0.8);
      out[i].push_back(vertices[i] + r * Eigen::Vector2d(std::cos(ang), std::sin(ang)));
    }
  return out;
}

}  // namespace qacc
