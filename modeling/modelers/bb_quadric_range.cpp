#include "modeling/modelers/bb_quadric_range.h"

#include <algorithm>
#include <limits>

namespace qacc {

QuadricRange rangeOnTetrahedron(const BBQuadric& q) {
  QuadricRange r{std::numeric_limits<double>::infinity(), -std::numeric_limits<double>::infinity()};
  for (int mask = 1; mask < 16; ++mask) {
    int idx[4], k = 0;
    for (int a = 0; a < 4; ++a)
      if (mask & (1 << a)) idx[k++] = a;
    double value;
    if (k == 1) {
      value = q.C(idx[0], idx[0]);  // a vertex: f(Va) = C(a, a)
    } else {
      // [C_SS, -1; 1ᵀ, 0] (λ, μ) = (0, 1).
      Eigen::MatrixXd A = Eigen::MatrixXd::Zero(k + 1, k + 1);
      Eigen::VectorXd rhs = Eigen::VectorXd::Zero(k + 1);
      for (int i = 0; i < k; ++i) {
        for (int j = 0; j < k; ++j) A(i, j) = q.C(idx[i], idx[j]);
        A(i, k) = -1.0;
        A(k, i) = 1.0;
      }
      rhs[k] = 1.0;
      const Eigen::FullPivLU<Eigen::MatrixXd> lu(A);
      if (!lu.isInvertible()) continue;  // flat along a line of the face: its boundary has the extremes
      const Eigen::VectorXd s = lu.solve(rhs);
      Eigen::Vector4d lambda = Eigen::Vector4d::Zero();
      bool inside = true;
      for (int i = 0; i < k; ++i) {
        inside = inside && s[i] > 0;
        lambda[idx[i]] = s[i];
      }
      if (!inside) continue;
      value = q.evalBarycentric(lambda);
    }
    r.min = std::min(r.min, value);
    r.max = std::max(r.max, value);
  }
  return r;
}

bool isEmptyExactly(const BBQuadric& q) {
  const double margin = 1e-9 * q.C.cwiseAbs().maxCoeff();
  const QuadricRange r = rangeOnTetrahedron(q);
  return r.min > margin || r.max < -margin;
}

}  // namespace qacc
