#include "modeling/simplex_spline3.h"

#include <algorithm>
#include <cmath>
#include <limits>
#include <set>
#include <stdexcept>
#include <type_traits>

#include "modeling/bb_tetra.h"

namespace qacc {
namespace {

using Vec = Eigen::Vector3d;

const Vec kTie(1.0, 0.3183098861837907, 0.1234567891234567);

double det4(const Vec& a, const Vec& b, const Vec& c, const Vec& d) { return (b - a).dot((c - a).cross(d - a)); }

struct Affine {
  Vec a;
  double b;
  double at(const Vec& u) const { return a.dot(u) + b; }
};

void barycentricForms(const Vec p[4], Affine l[4]) {
  Eigen::Matrix3d E;
  E.col(0) = p[1] - p[0];
  E.col(1) = p[2] - p[0];
  E.col(2) = p[3] - p[0];
  const Eigen::Matrix3d Ei = E.inverse();
  const Vec off = -(Ei * p[0]);
  l[0].a = Vec::Zero();
  l[0].b = 1.0;
  for (int j = 1; j <= 3; ++j) {
    l[j].a = Ei.row(j - 1).transpose();
    l[j].b = off[j - 1];
    l[0].a -= l[j].a;
    l[0].b -= l[j].b;
  }
}

double scaleOf(const std::vector<Vec>& V) {
  double s = 0;
  for (const Vec& v : V)
    for (const Vec& w : V) s = std::max(s, (v - w).cwiseAbs().maxCoeff());
  return s;
}

struct PolyT : Polynomial3 {
  PolyT(double c) : Polynomial3(Polynomial3::constant(c)) {}  // NOLINT
  PolyT(const Polynomial3& p) : Polynomial3(p) {}            // NOLINT
};

template <class T>
T simplexM(const std::vector<Vec>& V, const Vec& u, double scale) {
  if (V.size() < 4) return T(0.0);
  double best = 0;
  int bi[4] = {-1, -1, -1, -1};
  const int m = int(V.size());
  for (int i = 0; i < m; ++i)
    for (int j = i + 1; j < m; ++j)
      for (int k = j + 1; k < m; ++k)
        for (int l = k + 1; l < m; ++l) {
          const double d = std::fabs(det4(V[std::size_t(i)], V[std::size_t(j)], V[std::size_t(k)], V[std::size_t(l)]));
          if (d > best) {
            best = d;
            bi[0] = i, bi[1] = j, bi[2] = k, bi[3] = l;
          }
        }
  if (bi[0] < 0 || best <= 1e-12 * scale * scale * scale) return T(0.0);
  const Vec p[4] = {V[std::size_t(bi[0])], V[std::size_t(bi[1])], V[std::size_t(bi[2])], V[std::size_t(bi[3])]};
  Affine l[4];
  barycentricForms(p, l);
  if (V.size() == 4) {
    for (int j = 0; j < 4; ++j) {
      const double v = l[j].at(u);
      if (v > 0 || (v == 0 && l[j].a.dot(kTie) > 0)) continue;
      return T(0.0);
    }
    return T(1.0 / best);
  }
  T sum(0.0);
  for (int q = 0; q < 4; ++q) {
    std::vector<Vec> W;
    for (int s = 0; s < m; ++s)
      if (s != bi[q]) W.push_back(V[std::size_t(s)]);
    const T sub = simplexM<T>(W, u, scale);
    if constexpr (std::is_same<T, double>::value)
      sum += l[q].at(u) * sub;
    else
      sum = sum + Polynomial3::affine(l[q].a, l[q].b) * sub;
  }
  return sum;
}

// Canonical plane through three points (sorted), as (n, -n·p0).
Eigen::Vector4d canonicalPlane(Vec a, Vec b, Vec c) {
  auto less = [](const Vec& u, const Vec& v) {
    return u.x() < v.x() || (u.x() == v.x() && (u.y() < v.y() || (u.y() == v.y() && u.z() < v.z())));
  };
  Vec s[3] = {a, b, c};
  std::sort(s, s + 3, less);
  const Vec n = (s[1] - s[0]).cross(s[2] - s[0]);
  return Eigen::Vector4d(n.x(), n.y(), n.z(), -n.dot(s[0]));
}

// Vertices of the convex polyhedron ∩ half-spaces (all triples of planes).
std::vector<Vec> corners(const std::vector<HalfSpace>& hs, double eps) {
  std::vector<Vec> out;
  const std::size_t m = hs.size();
  for (std::size_t i = 0; i < m; ++i)
    for (std::size_t j = i + 1; j < m; ++j)
      for (std::size_t k = j + 1; k < m; ++k) {
        Eigen::Matrix3d A;
        A.row(0) = hs[i].p.head<3>().transpose();
        A.row(1) = hs[j].p.head<3>().transpose();
        A.row(2) = hs[k].p.head<3>().transpose();
        const double d = A.determinant();
        if (std::fabs(d) <= 1e-14 * A.rowwise().norm().prod()) continue;
        const Vec x = A.partialPivLu().solve(-Vec(hs[i].p.w(), hs[j].p.w(), hs[k].p.w()));
        bool in = true;
        for (const HalfSpace& h : hs) in = in && h.eval(x) <= eps * h.p.head<3>().norm();
        if (!in) continue;
        bool dup = false;
        for (const Vec& y : out) dup = dup || (y - x).norm() <= 1e3 * eps;
        if (!dup) out.push_back(x);
      }
  return out;
}

// Corners of cell ∩ {h <= 0} (keep = true) or cell ∩ {h >= 0}, from the parent's corners:
// the parent corners on that side plus the vertices on the new plane.
std::vector<Vec> childCorners(const std::vector<HalfSpace>& hs, const std::vector<Vec>& parent, const HalfSpace& h,
                              double eps) {
  std::vector<Vec> out;
  const double hn = h.p.head<3>().norm();
  for (const Vec& v : parent)
    if (h.eval(v) <= eps * hn) out.push_back(v);
  const std::size_t m = hs.size();
  for (std::size_t i = 0; i < m; ++i)
    for (std::size_t j = i + 1; j < m; ++j) {
      Eigen::Matrix3d A;
      A.row(0) = h.p.head<3>().transpose();
      A.row(1) = hs[i].p.head<3>().transpose();
      A.row(2) = hs[j].p.head<3>().transpose();
      const double d = A.determinant();
      if (std::fabs(d) <= 1e-14 * A.rowwise().norm().prod()) continue;
      const Vec x = A.partialPivLu().solve(-Vec(h.p.w(), hs[i].p.w(), hs[j].p.w()));
      bool in = true;
      for (const HalfSpace& g : hs) in = in && g.eval(x) <= eps * g.p.head<3>().norm();
      if (!in) continue;
      bool dup = false;
      for (const Vec& y : out) dup = dup || (y - x).norm() <= 1e3 * eps;
      if (!dup) out.push_back(x);
    }
  return out;
}

// A cell with volume: its corners are not all on one plane.
bool solid3(const std::vector<Vec>& c, double eps) {
  if (c.size() < 4) return false;
  Vec m = Vec::Zero();
  for (const Vec& v : c) m += v / double(c.size());
  Eigen::Matrix3d C = Eigen::Matrix3d::Zero();
  for (const Vec& v : c) C += (v - m) * (v - m).transpose();
  return Eigen::SelfAdjointEigenSolver<Eigen::Matrix3d>(C).eigenvalues()[0] > 1e4 * eps * eps;
}

// Does the triangle (a, b, c) cross the interior of the convex cell?
bool triangleCrosses(const std::vector<HalfSpace>& hs, const Vec& a, const Vec& b, const Vec& c, double eps) {
  std::vector<Vec> poly = {a, b, c};
  for (const HalfSpace& h : hs) {
    std::vector<Vec> next;
    const double hn = h.p.head<3>().norm();
    for (std::size_t i = 0; i < poly.size(); ++i) {
      const Vec& p = poly[i];
      const Vec& q = poly[(i + 1) % poly.size()];
      const double vp = h.eval(p) / hn, vq = h.eval(q) / hn;
      const bool ip = vp <= -eps, iq = vq <= -eps;  // strictly inside, with a margin
      if (ip) next.push_back(p);
      if (ip != iq) {
        const double t = (vp + eps) / (vp - vq);
        next.push_back(p + (q - p) * std::min(1.0, std::max(0.0, t)));
      }
    }
    poly.swap(next);
    if (poly.size() < 3) return false;
  }
  double area = 0;
  for (std::size_t i = 1; i + 1 < poly.size(); ++i) area += (poly[i] - poly[0]).cross(poly[i + 1] - poly[0]).norm();
  return area > 1e3 * eps * eps;
}

}  // namespace

SimplexSpline3::SimplexSpline3(int degree, std::vector<Vec> vertices, std::vector<std::array<int, 4>> tets,
                               std::vector<std::vector<Vec>> knots)
    : n_(degree), verts_(std::move(vertices)), tets_(std::move(tets)), knots_(std::move(knots)) {
  if (n_ < 0 || n_ > 3) throw std::invalid_argument("SimplexSpline3: degree must be in [0, 3]");
  if (knots_.size() != verts_.size()) throw std::invalid_argument("SimplexSpline3: one knot cloud per vertex");
  for (const auto& k : knots_)
    if (int(k.size()) != n_) throw std::invalid_argument("SimplexSpline3: each knot cloud needs degree extra knots");
  for (const auto& t : tets_)
    for (int v : t)
      if (v < 0 || v >= int(verts_.size())) throw std::invalid_argument("SimplexSpline3: vertex index out of range");
  coef_.assign(tets_.size(), std::vector<double>(multiIndices(n_).size(), 0.0));
}

std::vector<SimplexSpline3::Beta> SimplexSpline3::multiIndices(int n) {
  std::vector<Beta> out;
  for (const auto& m : BBTetra::multiIndices(n)) out.push_back(m);
  return out;
}

std::vector<Vec> SimplexSpline3::knotSet(std::size_t t, const Beta& b) const {
  std::vector<Vec> V;
  for (int c = 0; c < 4; ++c)
    for (int k = 0; k <= b[std::size_t(c)]; ++k) V.push_back(knot(tets_[t][std::size_t(c)], k));
  return V;
}

std::vector<Vec> SimplexSpline3::lowerSet(std::size_t t, const Beta& b) const {
  std::vector<Vec> U;
  for (int c = 0; c < 4; ++c)
    for (int k = 0; k < b[std::size_t(c)]; ++k) U.push_back(knot(tets_[t][std::size_t(c)], k));
  return U;
}

double SimplexSpline3::basis(std::size_t t, const Beta& b, const Vec& u) const {
  const auto V = knotSet(t, b);
  const auto& T = tets_[t];
  const double d = std::fabs(det4(knot(T[0], b[0]), knot(T[1], b[1]), knot(T[2], b[2]), knot(T[3], b[3])));
  return d * simplexM<double>(V, u, scaleOf(V));
}

double SimplexSpline3::eval(const Vec& u) const {
  const auto betas = multiIndices(n_);
  double s = 0;
  for (std::size_t t = 0; t < tets_.size(); ++t)
    for (std::size_t k = 0; k < betas.size(); ++k)
      if (coef_[t][k] != 0.0) s += coef_[t][k] * basis(t, betas[k], u);
  return s;
}

Polynomial3 SimplexSpline3::localPolynomial(const Vec& probe) const {
  const auto betas = multiIndices(n_);
  Polynomial3 s;
  for (std::size_t t = 0; t < tets_.size(); ++t)
    for (std::size_t k = 0; k < betas.size(); ++k) {
      if (coef_[t][k] == 0.0) continue;
      const auto V = knotSet(t, betas[k]);
      const auto& T = tets_[t];
      const auto& b = betas[k];
      const double d = std::fabs(det4(knot(T[0], b[0]), knot(T[1], b[1]), knot(T[2], b[2]), knot(T[3], b[3])));
      const PolyT m = simplexM<PolyT>(V, probe, scaleOf(V));
      s = s + static_cast<const Polynomial3&>(m) * (coef_[t][k] * d);
    }
  return s;
}

std::vector<std::vector<double>> SimplexSpline3::grevilleCoefficients(const Polynomial3& h) const {
  const auto betas = multiIndices(n_);
  std::vector<std::vector<double>> out(tets_.size(), std::vector<double>(betas.size()));
  for (std::size_t t = 0; t < tets_.size(); ++t)
    for (std::size_t k = 0; k < betas.size(); ++k) {
      const auto U = lowerSet(t, betas[k]);
      Vec xi = Vec::Zero();
      if (U.empty()) {
        for (int v : tets_[t]) xi += verts_[std::size_t(v)] / 4.0;
      } else {
        for (const Vec& q : U) xi += q / double(U.size());
      }
      out[t][k] = h.eval(xi);
    }
  return out;
}

std::vector<SimplexSpline3::Cell> SimplexSpline3::cells() const {
  double scale = 0;
  for (const Vec& v : verts_)
    for (const Vec& w : verts_) scale = std::max(scale, (v - w).norm());
  const double eps = 1e-10 * scale;
  const auto betas = multiIndices(n_);
  // Knot triangles (three distinct, non-collinear knots of one knot set).
  std::set<std::array<double, 9>> tris;
  for (std::size_t t = 0; t < tets_.size(); ++t)
    for (const auto& b : betas) {
      const auto V = knotSet(t, b);
      for (std::size_t i = 0; i < V.size(); ++i)
        for (std::size_t j = i + 1; j < V.size(); ++j)
          for (std::size_t k = j + 1; k < V.size(); ++k) {
            if ((V[j] - V[i]).cross(V[k] - V[i]).norm() <= eps * scale) continue;
            Vec s[3] = {V[i], V[j], V[k]};
            std::sort(s, s + 3, [](const Vec& u, const Vec& v) {
              return u.x() < v.x() || (u.x() == v.x() && (u.y() < v.y() || (u.y() == v.y() && u.z() < v.z())));
            });
            tris.insert({s[0].x(), s[0].y(), s[0].z(), s[1].x(), s[1].y(), s[1].z(), s[2].x(), s[2].y(), s[2].z()});
          }
    }
  std::vector<Cell> out;
  for (std::size_t t = 0; t < tets_.size(); ++t) {
    const auto& T = tets_[t];
    std::vector<HalfSpace> start;
    Vec centre = Vec::Zero();
    for (int v : T) centre += verts_[std::size_t(v)] / 4.0;
    for (int a = 0; a < 4; ++a) {
      const Eigen::Vector4d h = canonicalPlane(verts_[std::size_t(T[std::size_t((a + 1) % 4)])],
                                               verts_[std::size_t(T[std::size_t((a + 2) % 4)])],
                                               verts_[std::size_t(T[std::size_t((a + 3) % 4)])]);
      start.push_back(h.head<3>().dot(centre) + h.w() < 0 ? HalfSpace(h) : HalfSpace(h).opposite());
    }
    if (!domain_.isEmpty())
      for (int axis = 0; axis < 3; ++axis) {
        Eigen::Vector4d lo = Eigen::Vector4d::Zero(), hi = Eigen::Vector4d::Zero();
        lo[axis] = -1;
        lo[3] = domain_.min()[axis];
        hi[axis] = 1;
        hi[3] = -domain_.max()[axis];
        start.push_back(HalfSpace(lo));
        start.push_back(HalfSpace(hi));
      }
    struct Work {
      std::vector<HalfSpace> hs;
      std::vector<Vec> corners;
    };
    Work first{start, corners(start, eps)};
    if (!solid3(first.corners, eps)) continue;
    std::vector<Work> work = {first};
    Eigen::AlignedBox3d tb;
    for (const Vec& c : first.corners) tb.extend(c);
    for (const auto& s : tris) {
      const Vec a(s[0], s[1], s[2]), b(s[3], s[4], s[5]), c(s[6], s[7], s[8]);
      Eigen::AlignedBox3d sb;
      sb.extend(a);
      sb.extend(b);
      sb.extend(c);
      if (!tb.intersects(sb)) continue;
      const Eigen::Vector4d h = canonicalPlane(a, b, c);
      const double hn = h.head<3>().norm();
      std::vector<Work> next;
      next.reserve(work.size());
      for (auto& cell : work) {
        bool split = false;
        bool neg = false, pos = false;
        for (const Vec& v : cell.corners) {
          const double e = (h.head<3>().dot(v) + h.w()) / hn;
          neg = neg || e < -eps;
          pos = pos || e > eps;
        }
        if (neg && pos && triangleCrosses(cell.hs, a, b, c, eps)) {
          const HalfSpace ha(h), hb = HalfSpace(h).opposite();
          Work A{cell.hs, childCorners(cell.hs, cell.corners, ha, eps)};
          Work B{cell.hs, childCorners(cell.hs, cell.corners, hb, eps)};
          A.hs.push_back(ha);
          B.hs.push_back(hb);
          if (solid3(A.corners, eps) && solid3(B.corners, eps)) {
            next.push_back(std::move(A));
            next.push_back(std::move(B));
            split = true;
          }
        }
        if (!split) next.push_back(std::move(cell));
      }
      work.swap(next);
    }
    for (auto& wc : work) {
      Cell cell;
      cell.corners = wc.corners;
      for (const HalfSpace& h : wc.hs) {
        int on = 0;
        for (const Vec& v : cell.corners) on += std::fabs(h.eval(v)) <= 1e3 * eps * h.p.head<3>().norm();
        if (on >= 3) cell.faces.push_back(h);
      }
      Vec probe = Vec::Zero();
      for (const Vec& v : cell.corners) probe += v / double(cell.corners.size());
      cell.poly = localPolynomial(probe);
      cell.parent = t;
      Tetrahedron tet;
      for (int a = 0; a < 4; ++a) tet[std::size_t(a)] = verts_[std::size_t(T[std::size_t(a)])];
      BBTetra bb = BBTetra::fromPolynomial(cell.poly, tet);
      while (bb.degree() < 2) bb = bb.elevated();
      cell.crossed = bb.strictSign() == 0;
      out.push_back(std::move(cell));
    }
  }
  return out;
}

std::vector<Primitive> SimplexSpline3::toPrimitives(int material, int object) const {
  std::vector<Primitive> out;
  for (const Cell& c : cells()) {
    if (!c.crossed) continue;
    const Polynomial3& p = c.poly;
    Primitive prim;
    prim.quadric = Quadric::fromCoefficients(p.coefficient(2, 0, 0), p.coefficient(0, 2, 0), p.coefficient(0, 0, 2),
                                             0.5 * p.coefficient(1, 1, 0), 0.5 * p.coefficient(0, 1, 1),
                                             0.5 * p.coefficient(1, 0, 1), 0.5 * p.coefficient(1, 0, 0),
                                             0.5 * p.coefficient(0, 1, 0), 0.5 * p.coefficient(0, 0, 1),
                                             p.coefficient(0, 0, 0));
    prim.clip = c.faces;
    prim.material = material;
    prim.object = object;
    out.push_back(std::move(prim));
  }
  return out;
}

std::vector<std::vector<Eigen::Vector3d>> knotClouds3(const std::vector<Eigen::Vector3d>& vertices,
                                                     const std::vector<std::array<int, 4>>& tets, int degree,
                                                     bool g1, double radius) {
  std::vector<double> shortest(vertices.size(), std::numeric_limits<double>::infinity());
  for (const auto& t : tets)
    for (int a = 0; a < 4; ++a)
      for (int b = a + 1; b < 4; ++b) {
        const double l = (vertices[std::size_t(t[std::size_t(a)])] - vertices[std::size_t(t[std::size_t(b)])]).norm();
        shortest[std::size_t(t[std::size_t(a)])] = std::min(shortest[std::size_t(t[std::size_t(a)])], l);
        shortest[std::size_t(t[std::size_t(b)])] = std::min(shortest[std::size_t(t[std::size_t(b)])], l);
      }
  std::vector<std::vector<Eigen::Vector3d>> out(vertices.size());
  for (std::size_t i = 0; i < vertices.size(); ++i)
    for (int k = 1; k <= degree; ++k) {
      if (!g1 || !std::isfinite(shortest[i])) {
        out[i].push_back(vertices[i]);
        continue;
      }
      const double u = std::fmod(0.6180339887498949 * double(i * 7 + std::size_t(k) * 3 + 1), 1.0);
      const double w = std::fmod(0.7548776662466927 * double(i * 5 + std::size_t(k) * 11 + 2), 1.0);
      const double z = std::fmod(0.5698402909980532 * double(i * 3 + std::size_t(k) * 13 + 5), 1.0);
      const double th = 6.283185307179586 * u, ph = std::acos(2 * w - 1);
      const double r = radius * shortest[i] * (0.55 + 0.45 * z) * (k == 1 ? 1.0 : 0.8);
      out[i].push_back(vertices[i] + r * Eigen::Vector3d(std::sin(ph) * std::cos(th), std::sin(ph) * std::sin(th), std::cos(ph)));
    }
  return out;
}

}  // namespace qacc
