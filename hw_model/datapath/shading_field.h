// A shading field at a pixel: component k of an affine vector field of PrimitiveSetup
// (normal, view, point light; VectorSetup) at (u, v, z), (uv(u, v) << Fz) + cz · z, exact
// (Fz = depth_frac_bits). Shared by the 128-bit reference datapath and the 64-bit one
// (shading_arithmetic.cpp, shading_datapath64.cpp).
#pragma once
#include <cstdint>

#include "hw_model/datapath/fixed_point.h"
#include "hw_model/datapath/primitive_setup.h"

namespace qacc {

// Narrow: the coefficients fit 64 bits (value_bits + interp_frac_bits + 2 <= 64), as does the
// depth (depth_bits <= 40), so each product is one 64 x 64 -> 128-bit multiply on the host;
// the same value as the 128-bit products of the wide form.
template <bool Narrow>
inline i128 evalShadingField(const VectorSetup& f, int k, int u, int v, i128 z, int Fz) {
  const LinearCoefficients& c = f.uv[k];
  if constexpr (Narrow) {
    auto mul64 = [](i128 a, i128 b) { return i128(std::int64_t(a)) * i128(std::int64_t(b)); };
    const i128 uv = mul64(c.A, u) + mul64(c.B, v) + c.C;
    return i128((unsigned __int128)uv << Fz) + mul64(f.cz[k], z);
  }
  return shl(c.A * u + c.B * v + c.C, Fz) + f.cz[k] * z;
}

}  // namespace qacc
