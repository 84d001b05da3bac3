// A 3x3 linear solve by LU with partial pivoting, bit for bit Eigen's
// `A.partialPivLu().solve(b)` (Eigen 3.4, PartialPivLU.h and SolveTriangular.h): the same
// pivots (the first largest magnitude of the column), the same row swaps, quotients,
// products and differences in the same order, so the same result in every bit — including
// a zero pivot's infinities and NaNs — without the general, blocked machinery that made
// the decomposition cost about 1 000 instructions per solve. The exact piece boxes
// (piece_extent.cpp) solve one such system per candidate line.
// Tested against Eigen on random, scaled, singular and tied matrices (test_partial_pivot_solve3).
#pragma once
#include <cmath>
#include <utility>

#include <Eigen/Dense>

namespace qacc {

inline Eigen::Vector3d partialPivotSolve3(const Eigen::Matrix3d& A, const Eigen::Vector3d& b) {
  double a[3][3] = {{A(0, 0), A(0, 1), A(0, 2)}, {A(1, 0), A(1, 1), A(1, 2)}, {A(2, 0), A(2, 1), A(2, 2)}};
  int swapWith[2];
  // Eigen's unblocked_lu for a fixed size: columns 0 and 1 (the last pivot needs no work).
  for (int k = 0; k < 2; ++k) {
    int p = k;
    double best = std::abs(a[k][k]);
    for (int i = k + 1; i < 3; ++i) {
      const double v = std::abs(a[i][k]);
      if (v > best) {
        best = v;
        p = i;
      }
    }
    swapWith[k] = p;
    if (best != 0) {
      if (p != k)
        for (int j = 0; j < 3; ++j) std::swap(a[k][j], a[p][j]);
      for (int i = k + 1; i < 3; ++i) a[i][k] /= a[k][k];
    }
    for (int i = k + 1; i < 3; ++i)
      for (int j = k + 1; j < 3; ++j) a[i][j] -= a[i][k] * a[k][j];
  }
  // c = P b, then the unit lower and the upper triangular solves as Eigen unrolls them
  // (each row's products summed left to right, then subtracted, then divided).
  double c[3] = {b[0], b[1], b[2]};
  for (int k = 0; k < 2; ++k) std::swap(c[k], c[swapWith[k]]);
  c[1] -= a[1][0] * c[0];
  c[2] -= a[2][0] * c[0] + a[2][1] * c[1];
  c[2] /= a[2][2];
  c[1] -= a[1][2] * c[2];
  c[1] /= a[1][1];
  c[0] -= a[0][1] * c[1] + a[0][2] * c[2];
  c[0] /= a[0][0];
  return {c[0], c[1], c[2]};
}

}  // namespace qacc
