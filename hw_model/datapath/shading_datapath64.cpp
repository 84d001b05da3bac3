#include "hw_model/datapath/shading_datapath64.h"

#include <algorithm>

#include "hw_model/datapath/shading_field.h"
#include "hw_model/datapath/vector_normalizer64.h"

namespace qacc {

namespace {

using Reg = std::int64_t;

template <Rounding R>
inline Reg dot(const Reg a[3], const Reg b[3], int uf) {
  return shiftRoundFitR<R, Reg>(a[0] * b[0] + a[1] * b[1] + a[2] * b[2], uf);
}

// Inlined into shadePixel's one dispatch (by rounding, normaliser and coefficient width):
// no call per level, and the colour bytes leave in one register.
template <Rounding R, Normalizer Z, bool Narrow>
[[gnu::always_inline]] inline std::array<std::uint8_t, 3> shade64(const PrimitiveSetup& s, const LightingSetup& L, const HwConfig& cfg, int u, int v,
                                    i128 z, int cap) {
  const VectorNormalizer64<R, Z> unit(cfg);
  const int Fz = cfg.depth_frac_bits, uf = cfg.unit_frac_bits, cf = cfg.color_frac_bits;
  i128 raw[3];
  Reg N[3], V[3];
  if (cap >= 0) {
    for (int k = 0; k < 3; ++k) raw[k] = s.planes[std::size_t(cap)].capNormal[k];
  } else {
    for (int k = 0; k < 3; ++k) raw[k] = evalShadingField<Narrow>(s.normal, k, u, v, z, Fz);
  }
  unit.normalize(raw, N);
  for (int k = 0; k < 3; ++k) raw[k] = evalShadingField<Narrow>(s.view, k, u, v, z, Fz);
  unit.normalize(raw, V);
  if (dot<R>(N, V, uf) < 0)
    for (int k = 0; k < 3; ++k) N[k] = -N[k];  // two-sided
  const int mi = s.material >= 0 && s.material < int(L.materials64.size()) ? s.material : 0;
  const LightingSetup::Material64& m = L.materials64[std::size_t(mi)];
  const Reg one = Reg(1) << uf;
  Reg out[3] = {m.ambient[0], m.ambient[1], m.ambient[2]};
  // Lambert + Blinn-Phong of one light from the unit vector Lv towards it.
  auto light = [&](const Reg Lv[3], const Reg color[3]) {
    const Reg ndl = std::min(dot<R>(N, Lv, uf), one);
    if (ndl <= 0) return;
    Reg H[3];
    const Reg hs[3] = {Lv[0] + V[0], Lv[1] + V[1], Lv[2] + V[2]};
    unit.normalize(hs, H);
    const Reg ndh = std::clamp<Reg>(dot<R>(N, H, uf), 0, one);
    const Reg spec = m.specular[ndh];
    for (int k = 0; k < 3; ++k)
      out[k] += shiftRoundFitR<R, Reg>(color[k] * (shiftRoundFitR<R, Reg>(m.color[k] * ndl, uf) + spec), cf);
  };
  for (const LightingSetup::Directional64& d : L.directional64) light(d.dir, d.color);
  for (const LightingSetup::Point64& p : L.points64) {
    for (int k = 0; k < 3; ++k) raw[k] = evalShadingField<Narrow>(s.pointLights[std::size_t(p.point)], k, u, v, z, Fz);
    Reg Lv[3];
    unit.normalize(raw, Lv);
    light(Lv, p.color);
  }
  std::array<std::uint8_t, 3> rgb;
  const Reg top = Reg(1) << cf;
  for (int k = 0; k < 3; ++k) rgb[std::size_t(k)] = L.srgb[std::size_t(std::clamp<Reg>(out[k], 0, top))];
  return rgb;
}

}  // namespace

// shadePixel (shading_arithmetic.h) lives here, beside the datapath it dispatches to: one
// call a pixel, the instantiation picked by one switch.
std::array<std::uint8_t, 3> shadePixel(const PrimitiveSetup& s, const LightingSetup& L, const HwConfig& cfg, int u, int v,
                                       i128 z, int cap, OverflowCounter& ovf) {
  (void)ovf;  // colours above white clamp by design (as in every renderer), not an overflow
  if (!shadingDatapath64Applies(cfg)) return shadePixelWide(s, L, cfg, u, v, z, cap);
  constexpr Rounding T = Rounding::Truncate, N = Rounding::Nearest, E = Rounding::NearestEven;
  constexpr Normalizer Nw = Normalizer::Newton, Rc = Normalizer::Recurrence;
  const bool narrow = cfg.value_bits + cfg.interp_frac_bits + 2 <= 64;
  const int r = cfg.rounding == T ? 0 : cfg.rounding == N ? 1 : 2;
  const int key = r * 4 + (cfg.shading_normalizer == Nw ? 0 : 2) + (narrow ? 0 : 1);
  switch (key) {
    case 0: return shade64<T, Nw, true>(s, L, cfg, u, v, z, cap);
    case 1: return shade64<T, Nw, false>(s, L, cfg, u, v, z, cap);
    case 2: return shade64<T, Rc, true>(s, L, cfg, u, v, z, cap);
    case 3: return shade64<T, Rc, false>(s, L, cfg, u, v, z, cap);
    case 4: return shade64<N, Nw, true>(s, L, cfg, u, v, z, cap);
    case 5: return shade64<N, Nw, false>(s, L, cfg, u, v, z, cap);
    case 6: return shade64<N, Rc, true>(s, L, cfg, u, v, z, cap);
    case 7: return shade64<N, Rc, false>(s, L, cfg, u, v, z, cap);
    case 8: return shade64<E, Nw, true>(s, L, cfg, u, v, z, cap);
    case 9: return shade64<E, Nw, false>(s, L, cfg, u, v, z, cap);
    case 10: return shade64<E, Rc, true>(s, L, cfg, u, v, z, cap);
    default: return shade64<E, Rc, false>(s, L, cfg, u, v, z, cap);
  }
}

}  // namespace qacc
