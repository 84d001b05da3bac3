// Roots of a z² + 2 b z + c = 0 by the numerically stable form (design §3.1):
// q = −(b + sign(b) √Δ), z1 = q / a, z2 = c / q, with Δ = b² − a c.
// Avoids the cancellation of (−b ± √Δ) / a when b² ≫ |a c|. Handles a = 0 (one root
// −c / 2b) and returns the roots sorted; count = 0 when there is no real root.
#pragma once
#include <cmath>
#include <utility>

namespace qacc {

struct QuadraticRoots {
  int count = 0;
  double r[2] = {0, 0};
};

inline QuadraticRoots stableRoots(double a, double b, double c) {
  QuadraticRoots out;
  const double delta = b * b - a * c;
  if (delta < 0) return out;
  const double s = std::sqrt(delta);
  const double q = -(b + std::copysign(s, b));
  if (q == 0) {  // b = 0 and Δ = 0: a c = 0
    if (a != 0) {  // then c = 0: double root at 0
      out.count = 1;
      out.r[0] = 0;
    }
    return out;
  }
  if (a == 0) {
    out.count = 1;
    out.r[0] = c / q;
    return out;
  }
  double z1 = q / a, z2 = c / q;
  if (z2 < z1) std::swap(z1, z2);
  out.count = 2;
  out.r[0] = z1;
  out.r[1] = z2;
  return out;
}

}  // namespace qacc
