#include "modeling/splines/simplex_spline_base.h"

#include <algorithm>
#include <cmath>
#include <limits>
#include <stdexcept>
#include <string>

namespace qacc {
namespace {

// Fixed generic direction of the half-open rule.
template <int D>
Eigen::Matrix<double, D, 1> tieDirection() {
  if constexpr (D == 2)
    return Eigen::Vector2d(1.0, 0.3183098861837907);
  else
    return Eigen::Vector3d(1.0, 0.3183098861837907, 0.1234567891234567);
}

template <int D>
Eigen::Vector3d to3(const Eigen::Matrix<double, D, 1>& v) {
  Eigen::Vector3d r = Eigen::Vector3d::Zero();
  r.head<D>() = v;
  return r;
}

// d(p0..pD) = D! x signed volume.
template <int D>
double simplexDet(const Eigen::Matrix<double, D, 1>* const p[D + 1]) {
  Eigen::Matrix<double, D, D> E;
  for (int j = 0; j < D; ++j) E.col(j) = *p[j + 1] - *p[0];
  return E.determinant();
}

template <int D>
double scaleOf(const std::vector<Eigen::Matrix<double, D, 1>>& V) {
  double s = 0;
  for (const auto& v : V)
    for (const auto& w : V) s = std::max(s, (v - w).cwiseAbs().maxCoeff());
  return s;
}

// Dense polynomial of degree <= 4 in x, y, z: the local polynomials are accumulated here
// and converted to a Polynomial3 once.
struct Dense {
  static constexpr int S = 5;
  std::array<double, S * S * S> c{};
  int deg = 0;
  double& at(int i, int j, int k) { return c[std::size_t((i * S + j) * S + k)]; }
  double at(int i, int j, int k) const { return c[std::size_t((i * S + j) * S + k)]; }
  void mulAffine(const Eigen::Vector3d& a, double b) {
    Dense r;
    r.deg = deg + 1;
    for (int i = 0; i <= deg; ++i)
      for (int j = 0; i + j <= deg; ++j)
        for (int k = 0; i + j + k <= deg; ++k) {
          const double v = at(i, j, k);
          if (v == 0.0) continue;
          r.at(i, j, k) += b * v;
          r.at(i + 1, j, k) += a.x() * v;
          r.at(i, j + 1, k) += a.y() * v;
          r.at(i, j, k + 1) += a.z() * v;
        }
    *this = r;
  }
  void add(const Dense& o) {
    for (std::size_t q = 0; q < c.size(); ++q) c[q] += o.c[q];
    deg = std::max(deg, o.deg);
  }
  Polynomial3 poly() const {
    Polynomial3 p;
    for (int i = 0; i <= deg; ++i)
      for (int j = 0; i + j <= deg; ++j)
        for (int k = 0; i + j + k <= deg; ++k)
          if (at(i, j, k) != 0.0) p = p + Polynomial3::monomial(i, j, k, at(i, j, k));
    return p;
  }
};

}  // namespace

template <int D>
SimplexSplineBase<D>::SimplexSplineBase(const char* name, int degree, int maxDegree, std::vector<Vec> vertices,
                                        std::vector<Simplex> simplices, std::vector<std::vector<Vec>> knots)
    : n_(degree), verts_(std::move(vertices)), simplices_(std::move(simplices)), knots_(std::move(knots)) {
  const std::string who(name);
  if (n_ < 0 || n_ > maxDegree)
    throw std::invalid_argument(who + ": degree must be in [0, " + std::to_string(maxDegree) + "]");
  if (knots_.size() != verts_.size()) throw std::invalid_argument(who + ": one knot cloud per vertex");
  for (const auto& k : knots_)
    if (int(k.size()) != n_) throw std::invalid_argument(who + ": each knot cloud needs degree extra knots");
  for (const auto& s : simplices_) {
    const Vec* p[D + 1];
    for (int a = 0; a <= D; ++a) {
      const int v = s[std::size_t(a)];
      if (v < 0 || v >= int(verts_.size())) throw std::invalid_argument(who + ": vertex index out of range");
      p[a] = &verts_[std::size_t(v)];
    }
    if (simplexDet<D>(p) == 0)
      throw std::invalid_argument(who + (D == 2 ? ": degenerate triangle" : ": degenerate tetrahedron"));
  }
  coef_.assign(simplices_.size(), std::vector<double>(multiIndices(n_).size(), 0.0));
  compile();
}

template <int D>
std::vector<typename SimplexSplineBase<D>::Beta> SimplexSplineBase<D>::multiIndices(int n) {
  std::vector<Beta> out;
  Beta b{};
  // Descending lexicographic: the first entry from n down, then recursively the rest.
  auto rec = [&](auto&& self, int pos, int left) -> void {
    if (pos == D) {
      b[std::size_t(D)] = left;
      out.push_back(b);
      return;
    }
    for (int v = left; v >= 0; --v) {
      b[std::size_t(pos)] = v;
      self(self, pos + 1, left - v);
    }
  };
  rec(rec, 0, n);
  return out;
}

template <int D>
std::size_t SimplexSplineBase<D>::basisLeafBound(std::size_t simplices, int degree) {
  constexpr std::size_t kMax = std::numeric_limits<std::size_t>::max();
  auto times = [](std::size_t a, std::size_t b) { return b != 0 && a > kMax / b ? kMax : a * b; };
  std::size_t leaves = times(simplices, multiIndices(degree).size());
  for (int level = 0; level < degree; ++level) leaves = times(leaves, std::size_t(D + 1));
  return leaves;
}

template <int D>
std::size_t SimplexSplineBase<D>::leafCount() const {
  std::size_t leaves = 0;
  for (const Basis& b : basis_) leaves += b.leaves.size();
  return leaves;
}

template <int D>
std::vector<typename SimplexSplineBase<D>::Vec> SimplexSplineBase<D>::knotSet(std::size_t s, const Beta& b) const {
  std::vector<Vec> V;
  for (int c = 0; c <= D; ++c)
    for (int k = 0; k <= b[std::size_t(c)]; ++k) V.push_back(knot(simplices_[s][std::size_t(c)], k));
  return V;
}

template <int D>
std::vector<typename SimplexSplineBase<D>::Vec> SimplexSplineBase<D>::lowerSet(std::size_t s, const Beta& b) const {
  std::vector<Vec> U;
  for (int c = 0; c <= D; ++c)
    for (int k = 0; k < b[std::size_t(c)]; ++k) U.push_back(knot(simplices_[s][std::size_t(c)], k));
  return U;
}

template <int D>
void SimplexSplineBase<D>::setCoefficients(std::vector<std::vector<double>> c) {
  if (c.size() != simplices_.size()) throw std::invalid_argument("simplex spline: one coefficient list per simplex");
  for (const auto& l : c)
    if (l.size() != betas_.size()) throw std::invalid_argument("simplex spline: wrong number of coefficients");
  coef_ = std::move(c);
}

template <int D>
bool SimplexSplineBase<D>::inside(const Leaf& l, const Vec& u) {
  static const Vec tie = tieDirection<D>();
  for (const Affine& f : l.bary) {
    const double v = f.at(u);
    if (v > 0 || (v == 0 && f.a.dot(tie) > 0)) continue;
    return false;
  }
  return true;
}

template <int D>
double SimplexSplineBase<D>::Basis::value(const Vec& u, int n) const {
  if (!support.contains(u)) return 0.0;
  double s = 0;
  for (std::size_t l = 0; l < leaves.size(); ++l) {
    if (!inside(leaves[l], u)) continue;
    double v = leaves[l].weight;
    for (int f = 0; f < n; ++f) v *= factors[l * std::size_t(n) + std::size_t(f)].at(u);
    s += v;
  }
  return s;
}

template <int D>
void SimplexSplineBase<D>::compile() {
  betas_ = multiIndices(n_);
  basis_.clear();
  basis_.reserve(simplices_.size() * betas_.size());
  // The recursion M(u | V) = Σ_j λ_j M(u | V \ v_j), unrolled: `path` holds the λ met so far.
  std::vector<Affine> path;
  auto build = [&](auto&& self, const std::vector<Vec>& V, const std::vector<int>& ids, double scale, double weight,
                   Basis& B) -> void {
    const int m = int(V.size());
    if (m < D + 1) return;
    // The (D+1)-subset with the largest |d| (stable λ), first in lexicographic order.
    std::array<int, D + 1> c, best{};
    for (int a = 0; a <= D; ++a) c[std::size_t(a)] = a;
    double bestDet = 0;
    for (;;) {
      const Vec* p[D + 1];
      for (int a = 0; a <= D; ++a) p[a] = &V[std::size_t(c[std::size_t(a)])];
      const double d = std::fabs(simplexDet<D>(p));
      if (d > bestDet) {
        bestDet = d;
        best = c;
      }
      int a = D;
      while (a >= 0 && c[std::size_t(a)] == m - (D + 1) + a) --a;
      if (a < 0) break;
      ++c[std::size_t(a)];
      for (int b = a + 1; b <= D; ++b) c[std::size_t(b)] = c[std::size_t(b) - 1] + 1;
    }
    if (bestDet <= 1e-12 * std::pow(scale, D)) return;  // knots in a hyperplane: zero almost everywhere
    // Barycentric forms of the chosen simplex.
    Eigen::Matrix<double, D, D> E;
    const Vec& p0 = V[std::size_t(best[0])];
    for (int j = 0; j < D; ++j) E.col(j) = V[std::size_t(best[std::size_t(j) + 1])] - p0;
    const Eigen::Matrix<double, D, D> Ei = E.inverse();
    std::array<Affine, D + 1> l;
    l[0].a = Vec::Zero();
    l[0].b = 1.0;
    for (int j = 1; j <= D; ++j) {
      l[std::size_t(j)].a = Ei.row(j - 1).transpose();
      l[std::size_t(j)].b = -l[std::size_t(j)].a.dot(p0);
      l[0].a -= l[std::size_t(j)].a;
      l[0].b -= l[std::size_t(j)].b;
    }
    if (m == D + 1) {
      B.leaves.push_back(Leaf{l, weight / bestDet, {}});
      for (int a = 0; a <= D; ++a) B.leaves.back().knots[std::size_t(a)] = ids[std::size_t(a)];
      B.factors.insert(B.factors.end(), path.begin(), path.end());
      return;
    }
    std::vector<Vec> W;
    std::vector<int> Wids;
    for (int q = 0; q <= D; ++q) {
      W.clear();
      Wids.clear();
      for (int s = 0; s < m; ++s)
        if (s != best[std::size_t(q)]) {
          W.push_back(V[std::size_t(s)]);
          Wids.push_back(ids[std::size_t(s)]);
        }
      path.push_back(l[std::size_t(q)]);
      self(self, W, Wids, scale, weight, B);
      path.pop_back();
    }
  };
  for (std::size_t s = 0; s < simplices_.size(); ++s)
    for (std::size_t k = 0; k < betas_.size(); ++k) {
      Basis B;
      B.simplex = s;
      B.beta = k;
      const auto V = knotSet(s, betas_[k]);
      std::vector<int> ids;
      for (int c = 0; c <= D; ++c)
        for (int q = 0; q <= betas_[k][std::size_t(c)]; ++q) ids.push_back(knotId(simplices_[s][std::size_t(c)], q));
      for (const Vec& v : V) B.support.extend(v);
      Vec corner[D + 1];
      const Vec* p[D + 1];
      for (int a = 0; a <= D; ++a) {
        corner[a] = knot(simplices_[s][std::size_t(a)], betas_[k][std::size_t(a)]);
        p[a] = &corner[a];
      }
      build(build, V, ids, scaleOf<D>(V), std::fabs(simplexDet<D>(p)), B);
      basis_.push_back(std::move(B));
    }

  // Grid of the support boxes, cells about one support wide.
  gridBox_.setEmpty();
  Eigen::Array<double, D, 1> mean = Eigen::Array<double, D, 1>::Zero();
  for (const Basis& B : basis_) {
    gridBox_.extend(B.support);
    mean += B.support.sizes().array() / double(basis_.size());
  }
  grid_.clear();
  if (basis_.empty()) return;
  const Eigen::Array<double, D, 1> ext = gridBox_.sizes().array();
  for (int a = 0; a < D; ++a) {
    const double want = std::max(mean[a], ext[a] / 64.0);
    gridDims_[a] = want > 0 ? std::max(1, std::min(64, int(std::ceil(ext[a] / want)))) : 1;
    gridCell_[a] = ext[a] > 0 ? ext[a] / gridDims_[a] : 1.0;
  }
  grid_.assign(std::size_t(gridDims_.prod()), {});
  for (std::size_t i = 0; i < basis_.size(); ++i) {
    Eigen::Array<int, D, 1> lo, hi;
    for (int a = 0; a < D; ++a) {
      lo[a] = std::clamp(int(std::floor((basis_[i].support.min()[a] - gridBox_.min()[a]) / gridCell_[a])), 0, gridDims_[a] - 1);
      hi[a] = std::clamp(int(std::floor((basis_[i].support.max()[a] - gridBox_.min()[a]) / gridCell_[a])), 0, gridDims_[a] - 1);
    }
    Eigen::Array<int, D, 1> c = lo;
    for (;;) {
      int flat = 0;
      for (int a = D - 1; a >= 0; --a) flat = flat * gridDims_[a] + c[a];
      grid_[std::size_t(flat)].push_back(i);
      int a = 0;
      while (a < D && c[a] == hi[a]) c[a] = lo[a], ++a;
      if (a == D) break;
      ++c[a];
    }
  }
}

template <int D>
std::vector<std::size_t> SimplexSplineBase<D>::basisNear(const Box& box) const {
  std::vector<std::size_t> out;
  if (grid_.empty() || !gridBox_.intersects(box)) return out;
  Eigen::Array<int, D, 1> lo, hi;
  for (int a = 0; a < D; ++a) {
    lo[a] = std::clamp(int(std::floor((box.min()[a] - gridBox_.min()[a]) / gridCell_[a])), 0, gridDims_[a] - 1);
    hi[a] = std::clamp(int(std::floor((box.max()[a] - gridBox_.min()[a]) / gridCell_[a])), 0, gridDims_[a] - 1);
  }
  Eigen::Array<int, D, 1> c = lo;
  for (;;) {
    int flat = 0;
    for (int a = D - 1; a >= 0; --a) flat = flat * gridDims_[a] + c[a];
    for (std::size_t i : grid_[std::size_t(flat)])
      if (basis_[i].support.intersects(box)) out.push_back(i);
    int a = 0;
    while (a < D && c[a] == hi[a]) c[a] = lo[a], ++a;
    if (a == D) break;
    ++c[a];
  }
  std::sort(out.begin(), out.end());
  out.erase(std::unique(out.begin(), out.end()), out.end());
  return out;
}

template <int D>
double SimplexSplineBase<D>::basis(std::size_t s, const Beta& b, const Vec& u) const {
  const auto it = std::find(betas_.begin(), betas_.end(), b);
  if (it == betas_.end()) throw std::invalid_argument("simplex spline: multi-index of the wrong degree");
  return basis_[basisIndex(s, std::size_t(it - betas_.begin()))].value(u, n_);
}

template <int D>
double SimplexSplineBase<D>::eval(const Vec& u) const {
  double s = 0;
  for (std::size_t i : basisNear(Box(u, u))) {
    const double c = coefficientOf(basis_[i]);
    if (c != 0.0) s += c * basis_[i].value(u, n_);
  }
  return s;
}

template <int D>
Polynomial3 SimplexSplineBase<D>::localPolynomial(const Vec& probe) const {
  return localPolynomial(probe, basisNear(Box(probe, probe)));
}

template <int D>
Polynomial3 SimplexSplineBase<D>::localPolynomial(const Vec& probe, const std::vector<std::size_t>& candidates) const {
  Dense acc;
  for (std::size_t i : candidates) {
    const Basis& B = basis_[i];
    const double c = coefficientOf(B);
    if (c == 0.0 || !B.support.contains(probe)) continue;
    for (std::size_t l = 0; l < B.leaves.size(); ++l) {
      if (!inside(B.leaves[l], probe)) continue;
      Dense p;
      p.at(0, 0, 0) = c * B.leaves[l].weight;
      for (int f = 0; f < n_; ++f) {
        const Affine& a = B.factors[l * std::size_t(n_) + std::size_t(f)];
        p.mulAffine(to3<D>(a.a), a.b);
      }
      acc.add(p);
    }
  }
  return acc.poly();
}

template <int D>
template <class Rule>
std::vector<std::vector<double>> SimplexSplineBase<D>::coefficientsBy(Rule rule) const {
  std::vector<std::vector<double>> out(simplices_.size(), std::vector<double>(betas_.size()));
  for (std::size_t s = 0; s < simplices_.size(); ++s)
    for (std::size_t k = 0; k < betas_.size(); ++k) {
      std::vector<Eigen::Vector3d> U;
      for (const Vec& q : lowerSet(s, betas_[k])) U.push_back(to3<D>(q));
      Eigen::Vector3d xi = Eigen::Vector3d::Zero();  // the Greville point
      if (U.empty()) {
        for (int v : simplices_[s]) xi += to3<D>(verts_[std::size_t(v)]) / double(D + 1);
      } else {
        for (const auto& q : U) xi += q / double(U.size());
      }
      out[s][k] = rule(U, xi);
    }
  return out;
}

namespace {

// The blossom (polar form) of p(u) = uᵀ A u + g·u + c at U (|U| <= 2):
// P(a, b) = aᵀ A b + ½ g·(a + b) + c, P(a) = p(a), P() = c.
double blossom(const Eigen::Matrix3d& A, const Eigen::Vector3d& g, double c, const std::vector<Eigen::Vector3d>& U) {
  if (U.size() == 1) return U[0].dot(A * U[0]) + g.dot(U[0]) + c;
  if (U.size() == 2) return U[0].dot(A * U[1]) + 0.5 * g.dot(U[0] + U[1]) + c;
  return c;
}

}  // namespace

template <int D>
std::vector<std::vector<double>> SimplexSplineBase<D>::blossomCoefficients(const Polynomial3& p) const {
  if (n_ > 2) throw std::invalid_argument("blossomCoefficients: implemented for degree <= 2");
  if (p.degree() > n_) throw std::invalid_argument("blossomCoefficients: polynomial degree above the spline degree");
  Eigen::Matrix3d A;
  A << p.coefficient(2, 0, 0), 0.5 * p.coefficient(1, 1, 0), 0.5 * p.coefficient(1, 0, 1),  //
      0.5 * p.coefficient(1, 1, 0), p.coefficient(0, 2, 0), 0.5 * p.coefficient(0, 1, 1),     //
      0.5 * p.coefficient(1, 0, 1), 0.5 * p.coefficient(0, 1, 1), p.coefficient(0, 0, 2);
  const Eigen::Vector3d g(p.coefficient(1, 0, 0), p.coefficient(0, 1, 0), p.coefficient(0, 0, 1));
  const double c = p.coefficient(0, 0, 0);
  return coefficientsBy([&](const std::vector<Eigen::Vector3d>& U, const Eigen::Vector3d&) { return blossom(A, g, c, U); });
}

template <int D>
std::vector<std::vector<double>> SimplexSplineBase<D>::grevilleCoefficients(const Polynomial3& h) const {
  return coefficientsBy([&](const std::vector<Eigen::Vector3d>&, const Eigen::Vector3d& xi) { return h.eval(xi); });
}

template <int D>
std::vector<std::vector<double>> SimplexSplineBase<D>::taylorCoefficients(const Polynomial3& h) const {
  if (n_ > 2) throw std::invalid_argument("taylorCoefficients: implemented for degree <= 2");
  Polynomial3 d1[3], d2[3][3];
  for (int a = 0; a < 3; ++a) {
    d1[a] = h.derivative(a);
    for (int b = 0; b < 3; ++b) d2[a][b] = d1[a].derivative(b);
  }
  return coefficientsBy([&](const std::vector<Eigen::Vector3d>& U, const Eigen::Vector3d& xi) {
    // T(u) = h(xi) + ∇h(xi)·(u - xi) + ½ (u - xi)ᵀ H (u - xi), written as uᵀ A u + g·u + c.
    Eigen::Vector3d grad;
    Eigen::Matrix3d H;
    for (int a = 0; a < 3; ++a) {
      grad[a] = d1[a].eval(xi);
      for (int b = 0; b < 3; ++b) H(a, b) = d2[a][b].eval(xi);
    }
    const Eigen::Matrix3d A = 0.5 * H;
    const Eigen::Vector3d g = grad - H * xi;
    const double c = h.eval(xi) - grad.dot(xi) + 0.5 * xi.dot(H * xi);
    return blossom(A, g, c, U);
  });
}

template <int D>
double SimplexSplineBase<D>::knotReach() const {
  double r = 0;
  for (std::size_t i = 0; i < verts_.size(); ++i)
    for (const Vec& k : knots_[i]) r = std::max(r, (k - verts_[i]).norm());
  return r;
}

template <int D>
std::vector<std::vector<Eigen::Matrix<double, D, 1>>> simplexKnotClouds(
    const std::vector<Eigen::Matrix<double, D, 1>>& vertices, const std::vector<std::array<int, D + 1>>& simplices,
    int degree, bool g1, double radius) {
  std::vector<double> shortest(vertices.size(), std::numeric_limits<double>::infinity());
  for (const auto& t : simplices)
    for (int a = 0; a <= D; ++a)
      for (int b = a + 1; b <= D; ++b) {
        const std::size_t i = std::size_t(t[std::size_t(a)]), j = std::size_t(t[std::size_t(b)]);
        const double l = (vertices[i] - vertices[j]).norm();
        shortest[i] = std::min(shortest[i], l);
        shortest[j] = std::min(shortest[j], l);
      }
  std::vector<std::vector<Eigen::Matrix<double, D, 1>>> out(vertices.size());
  for (std::size_t i = 0; i < vertices.size(); ++i)
    for (int k = 1; k <= degree; ++k) {
      if (!g1 || !std::isfinite(shortest[i])) {
        out[i].push_back(vertices[i]);
        continue;
      }
      // Irregular but fixed directions and lengths (golden-ratio sequences).
      const double u = std::fmod(0.6180339887498949 * double(i * 7 + std::size_t(k) * 3 + 1), 1.0);
      const double w = std::fmod(0.7548776662466927 * double(i * 5 + std::size_t(k) * 11 + 2), 1.0);
      const double lengthScale = k == 1 ? 1.0 : 0.8;
      if constexpr (D == 2) {
        const double ang = 6.283185307179586 * u;
        const double r = radius * shortest[i] * (0.55 + 0.45 * w) * lengthScale;
        out[i].push_back(vertices[i] + r * Eigen::Vector2d(std::cos(ang), std::sin(ang)));
      } else {
        const double z = std::fmod(0.5698402909980532 * double(i * 3 + std::size_t(k) * 13 + 5), 1.0);
        const double th = 6.283185307179586 * u, ph = std::acos(2 * w - 1);
        const double r = radius * shortest[i] * (0.55 + 0.45 * z) * lengthScale;
        out[i].push_back(vertices[i] + r * Eigen::Vector3d(std::sin(ph) * std::cos(th), std::sin(ph) * std::sin(th), std::cos(ph)));
      }
    }
  return out;
}

template class SimplexSplineBase<2>;
template class SimplexSplineBase<3>;
template std::vector<std::vector<Eigen::Vector2d>> simplexKnotClouds<2>(const std::vector<Eigen::Vector2d>&,
                                                                        const std::vector<std::array<int, 3>>&, int,
                                                                        bool, double);
template std::vector<std::vector<Eigen::Vector3d>> simplexKnotClouds<3>(const std::vector<Eigen::Vector3d>&,
                                                                        const std::vector<std::array<int, 4>>&, int,
                                                                        bool, double);

}  // namespace qacc
