// partialPivotSolve3 (modeling/geometry/partial_pivot_solve3.h) gives Eigen's
// PartialPivLU<Matrix3d>::solve bit for bit: random matrices over many scales, rows of very
// different magnitudes, equal-magnitude pivots (ties), zero columns, singular and
// non-finite matrices, and the planes of piece boxes (two planes and their cross product).
#include <gtest/gtest.h>

#include <cmath>
#include <cstdint>
#include <cstring>
#include <limits>
#include <random>

#include "modeling/geometry/partial_pivot_solve3.h"

using namespace qacc;

namespace {

std::uint64_t bitsOf(double v) {
  std::uint64_t u;
  std::memcpy(&u, &v, sizeof u);
  return u;
}

// The same bits, NaNs compared as NaNs (their payloads are not specified).
bool sameBits(double a, double b) { return (std::isnan(a) && std::isnan(b)) || bitsOf(a) == bitsOf(b); }

int mismatches = 0;

void expectEigen(const Eigen::Matrix3d& A, const Eigen::Vector3d& b) {
  const Eigen::Vector3d e = A.partialPivLu().solve(b);
  const Eigen::Vector3d m = partialPivotSolve3(A, b);
  for (int i = 0; i < 3; ++i)
    if (!sameBits(e[i], m[i])) {
      if (++mismatches <= 5)
        ADD_FAILURE() << "x[" << i << "] " << m[i] << " vs Eigen " << e[i] << "\nA =\n" << A << "\nb = " << b.transpose();
    }
}

}  // namespace

TEST(PartialPivotSolve3, EqualsEigenBitForBit) {
  std::mt19937_64 rng(20261127);
  std::uniform_real_distribution<double> u(-1, 1);
  std::uniform_int_distribution<int> e(-40, 40), small(-2, 2), pick(0, 9);
  mismatches = 0;
  for (int n = 0; n < 200000; ++n) {
    Eigen::Matrix3d A;
    Eigen::Vector3d b;
    for (int i = 0; i < 3; ++i) {
      const double rowScale = std::ldexp(1.0, n % 3 == 0 ? e(rng) : 0);
      for (int j = 0; j < 3; ++j) {
        switch (pick(rng)) {
          case 0: A(i, j) = 0; break;                         // zeros: zero pivots, skipped updates
          case 1: A(i, j) = double(small(rng)) * rowScale; break;  // small integers: ties of magnitude
          default: A(i, j) = u(rng) * rowScale; break;
        }
      }
      b[i] = pick(rng) == 0 ? 0.0 : u(rng) * std::ldexp(1.0, e(rng));
    }
    if (n % 7 == 0) A.row(2) = A.row(0) * 2.0;  // singular
    if (n % 11 == 0) {                           // a line's system: two planes and their direction
      const Eigen::Vector3d na(u(rng), u(rng), u(rng)), nb(u(rng), u(rng), u(rng));
      A << na.transpose(), nb.transpose(), na.cross(nb).transpose();
    }
    expectEigen(A, b);
  }
  const double inf = std::numeric_limits<double>::infinity(), nan = std::numeric_limits<double>::quiet_NaN();
  Eigen::Matrix3d A = Eigen::Matrix3d::Zero();
  expectEigen(A, {1, 2, 3});
  A << 1, 2, 3, -1, 2, 3, 1, -2, 3;  // every pivot tied
  expectEigen(A, {1, -1, 0.5});
  A << inf, 1, 2, 3, 4, 5, 6, 7, 8;
  expectEigen(A, {1, 2, 3});
  A << nan, 1, 2, 3, 4, 5, 6, 7, 8;
  expectEigen(A, {1, 2, 3});
  A << 1, 2, 3, 4, 5, 6, 7, 8, 9;
  expectEigen(A, {1, 2, 3});
  EXPECT_EQ(mismatches, 0);
}
