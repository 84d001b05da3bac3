#include "modeling/algebraic/bb_tetra.h"

#include <algorithm>
#include <stdexcept>
#include <string>

namespace qacc {
namespace {

constexpr int kMaxDegree = 32;

struct IndexTables {
  std::vector<std::vector<MultiIndex4>> list;  // list[n] = multi-indices of degree n
  std::vector<std::vector<int>> lookup;        // lookup[n][(i*(n+1)+j)*(n+1)+k]
  std::vector<double> factorial;
  IndexTables() {
    list.resize(kMaxDegree + 1);
    lookup.resize(kMaxDegree + 1);
    for (int n = 0; n <= kMaxDegree; ++n) {
      const int s = n + 1;
      lookup[std::size_t(n)].assign(std::size_t(s * s * s), -1);
      for (int i = n; i >= 0; --i)
        for (int j = n - i; j >= 0; --j)
          for (int k = n - i - j; k >= 0; --k) {
            const int l = n - i - j - k;
            lookup[std::size_t(n)][std::size_t((i * s + j) * s + k)] = int(list[std::size_t(n)].size());
            list[std::size_t(n)].push_back({i, j, k, l});
          }
    }
    factorial.resize(kMaxDegree + 1);
    factorial[0] = 1.0;
    for (int m = 1; m <= kMaxDegree; ++m) factorial[std::size_t(m)] = factorial[std::size_t(m) - 1] * m;
  }
};

const IndexTables& tables() {
  static const IndexTables t;
  return t;
}

void checkDegree(int n) {
  if (n < 0 || n > kMaxDegree)
    throw std::invalid_argument("BBTetra: degree " + std::to_string(n) + " outside [0, " +
                                std::to_string(kMaxDegree) + "]");
}

// Homogeneous polynomial of degree m in λ0..λ3, stored over multiIndices(m).
using Hom = std::vector<double>;

Hom homMul(const Hom& p, int dp, const Hom& q, int dq) {
  const auto& lp = BBTetra::multiIndices(dp);
  const auto& lq = BBTetra::multiIndices(dq);
  Hom r(BBTetra::multiIndices(dp + dq).size(), 0.0);
  for (std::size_t u = 0; u < lp.size(); ++u) {
    if (p[u] == 0.0) continue;
    for (std::size_t v = 0; v < lq.size(); ++v) {
      if (q[v] == 0.0) continue;
      const MultiIndex4 s = {lp[u][0] + lq[v][0], lp[u][1] + lq[v][1], lp[u][2] + lq[v][2], lp[u][3] + lq[v][3]};
      r[std::size_t(BBTetra::index(dp + dq, s))] += p[u] * q[v];
    }
  }
  return r;
}

}  // namespace

BBTetra::BBTetra(int degree, const Tetrahedron& v) : n_(degree), V_(v) {
  checkDegree(degree);
  c_.assign(multiIndices(degree).size(), 0.0);
}

const std::vector<MultiIndex4>& BBTetra::multiIndices(int n) {
  checkDegree(n);
  return tables().list[std::size_t(n)];
}

int BBTetra::index(int n, const MultiIndex4& a) {
  checkDegree(n);
  if (a[0] < 0 || a[1] < 0 || a[2] < 0 || a[3] < 0 || a[0] + a[1] + a[2] + a[3] != n)
    throw std::invalid_argument("BBTetra: multi-index does not have degree " + std::to_string(n));
  const int s = n + 1;
  return tables().lookup[std::size_t(n)][std::size_t((a[0] * s + a[1]) * s + a[2])];
}

double BBTetra::multinomial(int n, const MultiIndex4& a) {
  const auto& f = tables().factorial;
  return f[std::size_t(n)] / (f[std::size_t(a[0])] * f[std::size_t(a[1])] * f[std::size_t(a[2])] * f[std::size_t(a[3])]);
}

BBTetra BBTetra::fromPolynomial(const Polynomial3& f, const Tetrahedron& v) {
  const int n = f.degree();
  BBTetra b(n, v);
  // Linear forms x(λ), y(λ), z(λ) and 1 = Σλ, as degree-1 homogeneous polynomials.
  Hom L[4];
  for (int axis = 0; axis < 4; ++axis) {
    L[axis].assign(4, 0.0);
    for (int a = 0; a < 4; ++a) {
      MultiIndex4 e = {0, 0, 0, 0};
      e[std::size_t(a)] = 1;
      L[axis][std::size_t(index(1, e))] = axis < 3 ? v[std::size_t(a)][axis] : 1.0;
    }
  }
  // pw[axis][e] = L[axis]^e.
  std::vector<Hom> pw[4];
  for (int axis = 0; axis < 4; ++axis) {
    pw[axis].resize(std::size_t(n) + 1);
    pw[axis][0] = {1.0};
    for (int e = 1; e <= n; ++e) pw[axis][std::size_t(e)] = homMul(pw[axis][std::size_t(e) - 1], e - 1, L[axis], 1);
  }
  Hom acc(multiIndices(n).size(), 0.0);
  for (const auto& t : f.terms()) {
    const int d = t.i + t.j + t.k;
    Hom p = homMul(pw[0][std::size_t(t.i)], t.i, pw[1][std::size_t(t.j)], t.j);
    p = homMul(p, t.i + t.j, pw[2][std::size_t(t.k)], t.k);
    p = homMul(p, d, pw[3][std::size_t(n - d)], n - d);
    for (std::size_t u = 0; u < acc.size(); ++u) acc[u] += t.a * p[u];
  }
  const auto& list = multiIndices(n);
  for (std::size_t u = 0; u < list.size(); ++u) b.c_[u] = acc[u] / multinomial(n, list[u]);
  return b;
}

BBTetra BBTetra::fromBBQuadric(const BBQuadric& q) {
  BBTetra b(2, q.V);
  for (int a = 0; a < 4; ++a)
    for (int c = a; c < 4; ++c) {
      MultiIndex4 m = {0, 0, 0, 0};
      m[std::size_t(a)] += 1;
      m[std::size_t(c)] += 1;
      b.setCoefficient(m, q.C(a, c));
    }
  return b;
}

BBQuadric BBTetra::toBBQuadric() const {
  if (n_ != 2) throw std::invalid_argument("BBTetra::toBBQuadric: degree is " + std::to_string(n_) + ", not 2");
  Eigen::Matrix4d C;
  for (int a = 0; a < 4; ++a)
    for (int c = 0; c < 4; ++c) {
      MultiIndex4 m = {0, 0, 0, 0};
      m[std::size_t(a)] += 1;
      m[std::size_t(c)] += 1;
      C(a, c) = coefficient(m);
    }
  return BBQuadric(V_, C);
}

Eigen::Vector4d BBTetra::barycentric(const Eigen::Vector3d& p) const {
  Eigen::Matrix3d E;
  E.col(0) = V_[1] - V_[0];
  E.col(1) = V_[2] - V_[0];
  E.col(2) = V_[3] - V_[0];
  const Eigen::Vector3d l = E.partialPivLu().solve(p - V_[0]);
  return Eigen::Vector4d(1.0 - l.sum(), l.x(), l.y(), l.z());
}

double BBTetra::evalBarycentric(const Eigen::Vector4d& lambda) const {
  std::vector<double> b = c_;
  for (int r = n_; r >= 1; --r) {
    const auto& lower = multiIndices(r - 1);
    std::vector<double> nb(lower.size());
    for (std::size_t u = 0; u < lower.size(); ++u) {
      double s = 0.0;
      for (int a = 0; a < 4; ++a) {
        MultiIndex4 m = lower[u];
        m[std::size_t(a)] += 1;
        s += lambda[a] * b[std::size_t(index(r, m))];
      }
      nb[u] = s;
    }
    b.swap(nb);
  }
  return b[0];
}

int BBTetra::strictSign() const {
  bool pos = true, neg = true;
  for (double c : c_) {
    pos = pos && c > 0.0;
    neg = neg && c < 0.0;
  }
  return pos ? 1 : neg ? -1 : 0;
}

BBTetra BBTetra::elevated() const {
  BBTetra e(n_ + 1, V_);
  const auto& list = multiIndices(n_ + 1);
  for (std::size_t u = 0; u < list.size(); ++u) {
    double s = 0.0;
    for (int a = 0; a < 4; ++a) {
      if (list[u][std::size_t(a)] == 0) continue;
      MultiIndex4 m = list[u];
      m[std::size_t(a)] -= 1;
      s += list[u][std::size_t(a)] * coefficient(m);
    }
    e.c_[u] = s / (n_ + 1);
  }
  return e;
}

BBTetra BBTetra::reducedOnce() const {
  if (n_ < 1) throw std::invalid_argument("BBTetra::reducedOnce: degree 0 cannot be reduced");
  const int m = n_ - 1;
  const auto& list = multiIndices(m);
  // approx[a]: the degree-m simplex inverting elevation from vertex a (Petersen (5.4)).
  std::vector<std::vector<double>> approx(4, std::vector<double>(list.size(), 0.0));
  for (int a = 0; a < 4; ++a) {
    std::vector<std::size_t> order(list.size());
    for (std::size_t u = 0; u < order.size(); ++u) order[u] = u;
    std::stable_sort(order.begin(), order.end(), [&](std::size_t u, std::size_t v) {
      return list[u][std::size_t(a)] > list[v][std::size_t(a)];
    });
    auto& A = approx[std::size_t(a)];
    for (std::size_t u : order) {
      MultiIndex4 alpha = list[u];
      alpha[std::size_t(a)] += 1;  // α = β + e_a, α_a >= 1
      double s = n_ * coefficient(alpha);
      for (int b = 0; b < 4; ++b) {
        if (b == a || alpha[std::size_t(b)] == 0) continue;
        MultiIndex4 g = alpha;
        g[std::size_t(b)] -= 1;  // α - e_b: component a is β_a + 1, already computed
        s -= alpha[std::size_t(b)] * A[std::size_t(index(m, g))];
      }
      A[u] = s / alpha[std::size_t(a)];
    }
  }
  BBTetra r(m, V_);
  for (std::size_t u = 0; u < list.size(); ++u) {
    const int mx = *std::max_element(list[u].begin(), list[u].end());
    double s = 0.0;
    int cnt = 0;
    for (int a = 0; a < 4; ++a)
      if (list[u][std::size_t(a)] == mx) {
        s += approx[std::size_t(a)][u];
        ++cnt;
      }
    r.c_[u] = s / cnt;
  }
  return r;
}

BBTetra BBTetra::reducedTo(int degree) const {
  if (degree > n_) throw std::invalid_argument("BBTetra::reducedTo: target degree above the current one");
  BBTetra r = *this;
  while (r.n_ > degree) r = r.reducedOnce();
  return r;
}

BBTetra reduceQuarticClosedForm(const BBTetra& B) {
  if (B.degree() != 4) throw std::invalid_argument("reduceQuarticClosedForm: degree must be 4");
  BBTetra A(2, B.vertices());
  auto e = [](int a, int ka, int b, int kb) {
    MultiIndex4 m = {0, 0, 0, 0};
    m[std::size_t(a)] += ka;
    m[std::size_t(b)] += kb;
    return m;
  };
  for (int a = 0; a < 4; ++a) A.setCoefficient(e(a, 2, a, 0), B.coefficient(e(a, 4, a, 0)));
  for (int a = 0; a < 4; ++a)
    for (int b = a + 1; b < 4; ++b)
      A.setCoefficient(e(a, 1, b, 1), -0.5 * B.coefficient(e(a, 4, b, 0)) + B.coefficient(e(a, 3, b, 1)) -
                                           0.5 * B.coefficient(e(b, 4, a, 0)) + B.coefficient(e(a, 1, b, 3)));
  return A;
}

BBTetra reduceByVertexRule(const Polynomial3& f, const Tetrahedron& v) {
  BBTetra A(2, v);
  double val[4];
  Eigen::Vector3d grad[4];
  for (int a = 0; a < 4; ++a) {
    val[a] = f.eval(v[std::size_t(a)]);
    grad[a] = f.gradient(v[std::size_t(a)]);
    MultiIndex4 m = {0, 0, 0, 0};
    m[std::size_t(a)] = 2;
    A.setCoefficient(m, val[a]);
  }
  for (int a = 0; a < 4; ++a)
    for (int b = a + 1; b < 4; ++b) {
      MultiIndex4 m = {0, 0, 0, 0};
      m[std::size_t(a)] = 1;
      m[std::size_t(b)] = 1;
      const Eigen::Vector3d d = v[std::size_t(b)] - v[std::size_t(a)];
      A.setCoefficient(m, 0.5 * (val[a] + 0.5 * grad[a].dot(d) + val[b] - 0.5 * grad[b].dot(d)));
    }
  return A;
}

}  // namespace qacc
