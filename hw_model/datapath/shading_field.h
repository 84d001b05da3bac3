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
//
// The field in two parts: the affine part uv(u, v) << Fz, as the bits of a 128-bit register
// (along a row it advances by A << Fz a pixel, the same bits modulo 2^128: shadeSpan's
// forward differences), and the depth part cz · z.
template <bool Narrow>
inline unsigned __int128 shadingFieldRowPart(const VectorSetup& f, int k, int u, int v, int Fz) {
  const LinearCoefficients& c = f.uv[k];
  i128 uv;
  if constexpr (Narrow) {
    auto mul64 = [](i128 a, i128 b) { return i128(std::int64_t(a)) * i128(std::int64_t(b)); };
    uv = mul64(c.A, u) + mul64(c.B, v) + c.C;
  } else {
    uv = c.A * u + c.B * v + c.C;
  }
  return (unsigned __int128)uv << Fz;
}
template <bool Narrow>
inline i128 shadingFieldDepthPart(i128 cz, i128 z) {
  if constexpr (Narrow) return i128(std::int64_t(cz)) * i128(std::int64_t(z));
  return cz * z;
}
template <bool Narrow>
inline i128 evalShadingField(const VectorSetup& f, int k, int u, int v, i128 z, int Fz) {
  return i128(shadingFieldRowPart<Narrow>(f, k, u, v, Fz) + (unsigned __int128)shadingFieldDepthPart<Narrow>(f.cz[k], z));
}

}  // namespace qacc
