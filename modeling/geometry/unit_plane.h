// A plane scaled to unit size by a power of two: the largest coefficient lands in [0.5, 1).
// A plane is scale-free, and a power of two is exact and keeps every sign, so a half-space's
// ownership (half_space.h) and its opposite are unchanged, and a plane through a point with
// exactly representable coordinates still evaluates to exactly zero there (a division by
// the largest coefficient rounds). Coefficients near 1e300 or 1e-300 would otherwise
// overflow or underflow in transforms and in the setup arithmetic.
#pragma once
#include <cmath>

#include <Eigen/Dense>

#include "modeling/geometry/half_space.h"

namespace qacc {

inline Eigen::Vector4d unitPlane(const Eigen::Vector4d& v) {
  const double m = v.cwiseAbs().maxCoeff();
  if (!(m > 0) || !std::isfinite(m)) return v;
  int ex;
  std::frexp(m, &ex);
  return Eigen::Vector4d(std::ldexp(v[0], -ex), std::ldexp(v[1], -ex), std::ldexp(v[2], -ex), std::ldexp(v[3], -ex));
}

inline HalfSpace unitPlane(const HalfSpace& h) { return HalfSpace(unitPlane(h.p), h.owns_boundary); }

}  // namespace qacc
