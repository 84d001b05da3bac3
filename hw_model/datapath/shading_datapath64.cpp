#include "hw_model/datapath/shading_datapath64.h"

#include <algorithm>
#include <type_traits>
#include <vector>

#include "hw_model/datapath/shading_field.h"
#include "hw_model/datapath/vector_normalizer64.h"

namespace qacc {

namespace {

using Reg = std::int64_t;

template <Rounding R>
inline Reg dot(const Reg a[3], const Reg b[3], int uf) {
  return shiftRoundFitR<R, Reg>(a[0] * b[0] + a[1] * b[1] + a[2] * b[2], uf);
}

// What every pixel of a span reads besides its fields: the formats, the material, the
// lights and the ROMs, copied out of the configuration, the lighting and the primitive once
// a span, so that the loop keeps them in registers (a colour byte stored through rgb may
// alias anything, and would make the compiler load them again after every pixel).
template <Rounding R, Normalizer Z>
struct SpanConstants {
  VectorNormalizer64<R, Z> unit;
  int Fz, uf, cf;
  Reg one, top;
  Reg color[3], ambient[3];
  const std::int32_t* specular;
  const LightingSetup::Directional64* directional;
  std::size_t directionals;
  const LightingSetup::Point64* points;
  std::size_t pointCount;
  const VectorSetup* pointFields;
  const PlaneSetup* planes;
  const std::uint8_t* srgb;
  SpanConstants(const PrimitiveSetup& s, const LightingSetup& L, const HwConfig& cfg)
      : unit(cfg), Fz(cfg.depth_frac_bits), uf(cfg.unit_frac_bits), cf(cfg.color_frac_bits), one(Reg(1) << uf),
        top(Reg(1) << cf), directional(L.directional64.data()), directionals(L.directional64.size()),
        points(L.points64.data()), pointCount(L.points64.size()), pointFields(s.pointLights.data()),
        planes(s.planes.data()), srgb(L.srgb.data()) {
    const int mi = s.material >= 0 && s.material < int(L.materials64.size()) ? s.material : 0;
    const LightingSetup::Material64& m = L.materials64[std::size_t(mi)];
    for (int k = 0; k < 3; ++k) {
      color[k] = m.color[k];
      ambient[k] = m.ambient[k];
    }
    specular = m.specular;
  }
};

// The shading of one pixel from its normal and view fields (raw, exact; the normal is
// unused on a cap): inlined into shadeSpan's one dispatch (by rounding, normaliser and
// coefficient width), no call per level, the colour bytes in one register.
template <Rounding R, Normalizer Z>
[[gnu::always_inline]] inline std::array<std::uint8_t, 3> shadeFields(const SpanConstants<R, Z>& c, int cap,
                                                                      const i128 rawN[3], const i128 rawV[3],
                                                                      const i128* rawP) {
  const VectorNormalizer64<R, Z>& unit = c.unit;
  const int uf = c.uf;
  Reg N[3], V[3];
  if (cap >= 0) {
    i128 capN[3];
    for (int k = 0; k < 3; ++k) capN[k] = c.planes[cap].capNormal[k];
    unit.normalize(capN, N);
  } else {
    unit.normalize(rawN, N);
  }
  unit.normalize(rawV, V);
  if (dot<R>(N, V, uf) < 0)
    for (int k = 0; k < 3; ++k) N[k] = -N[k];  // two-sided
  Reg out[3] = {c.ambient[0], c.ambient[1], c.ambient[2]};
  // Lambert + Blinn-Phong of one light from the unit vector Lv towards it.
  auto light = [&](const Reg Lv[3], const Reg color[3]) {
    const Reg ndl = std::min(dot<R>(N, Lv, uf), c.one);
    if (ndl <= 0) return;
    Reg H[3];
    const Reg hs[3] = {Lv[0] + V[0], Lv[1] + V[1], Lv[2] + V[2]};
    unit.normalize(hs, H);
    const Reg ndh = std::clamp<Reg>(dot<R>(N, H, uf), 0, c.one);
    const Reg spec = c.specular[ndh];
    for (int k = 0; k < 3; ++k)
      out[k] += shiftRoundFitR<R, Reg>(color[k] * (shiftRoundFitR<R, Reg>(c.color[k] * ndl, uf) + spec), c.cf);
  };
  for (std::size_t i = 0; i < c.directionals; ++i) light(c.directional[i].dir, c.directional[i].color);
  for (std::size_t i = 0; i < c.pointCount; ++i) {
    Reg Lv[3];
    unit.normalize(rawP + 3 * i, Lv);
    light(Lv, c.points[i].color);
  }
  std::array<std::uint8_t, 3> rgb;
  for (int k = 0; k < 3; ++k) rgb[std::size_t(k)] = c.srgb[std::clamp<Reg>(out[k], 0, c.top)];
  return rgb;
}

// The n winners of a row: the normal and view fields' affine parts advance by forward
// differences (the same bits as evalShadingField at each pixel: shading_field.h).
template <Rounding R, Normalizer Z, bool Narrow>
void shadeSpan64(const PrimitiveSetup& s, const LightingSetup& L, const HwConfig& cfg, int u, int v, int n,
                 const ZEntry* winners, std::array<std::uint8_t, 3>* rgb) {
  using U = unsigned __int128;
  const SpanConstants<R, Z> c(s, L, cfg);
  const int Fz = c.Fz;
  U rowN[3], rowV[3], stepN[3], stepV[3];
  i128 czN[3], czV[3];
  for (int k = 0; k < 3; ++k) {
    rowN[k] = shadingFieldRowPart<Narrow>(s.normal, k, u, v, Fz);
    rowV[k] = shadingFieldRowPart<Narrow>(s.view, k, u, v, Fz);
    stepN[k] = U(s.normal.uv[k].A) << Fz;
    stepV[k] = U(s.view.uv[k].A) << Fz;
    czN[k] = s.normal.cz[k];
    czV[k] = s.view.cz[k];
  }
  // The point lights' fields (towards each light), likewise: three components a light in a
  // per-thread scratch that keeps its storage from span to span.
  const std::size_t np3 = 3 * c.pointCount;
  thread_local std::vector<U> pointScratch;
  thread_local std::vector<i128> pointRaw;
  pointScratch.resize(2 * np3);
  pointRaw.resize(np3);
  U* rowP = pointScratch.data();
  U* stepP = rowP + np3;
  i128* rawP = pointRaw.data();
  for (std::size_t j = 0; j < c.pointCount; ++j)
    for (int k = 0; k < 3; ++k) {
      const VectorSetup& f = c.pointFields[c.points[j].point];
      rowP[3 * j + std::size_t(k)] = shadingFieldRowPart<Narrow>(f, k, u, v, Fz);
      stepP[3 * j + std::size_t(k)] = U(f.uv[k].A) << Fz;
    }
  for (int i = 0; i < n; ++i) {
    const i128 z = winners[i].depth;
    const int cap = int(winners[i].cap);
    i128 rawN[3], rawV[3];
    for (int k = 0; k < 3; ++k) {
      rawN[k] = i128(rowN[k] + U(shadingFieldDepthPart<Narrow>(czN[k], z)));
      rawV[k] = i128(rowV[k] + U(shadingFieldDepthPart<Narrow>(czV[k], z)));
      rowN[k] += stepN[k];
      rowV[k] += stepV[k];
    }
    for (std::size_t j = 0; j < c.pointCount; ++j) {
      const VectorSetup& f = c.pointFields[c.points[j].point];
      for (std::size_t k = 0; k < 3; ++k) {
        rawP[3 * j + k] = i128(rowP[3 * j + k] + U(shadingFieldDepthPart<Narrow>(f.cz[k], z)));
        rowP[3 * j + k] += stepP[3 * j + k];
      }
    }
    rgb[i] = shadeFields<R, Z>(c, cap, rawN, rawV, rawP);
  }
}

// The instantiation of the configuration: one switch by rounding, normaliser and
// coefficient width, F called with the three as template constants.
template <typename F>
[[gnu::always_inline]] inline auto dispatch64(const HwConfig& cfg, F&& f) {
  constexpr Rounding T = Rounding::Truncate, N = Rounding::Nearest, E = Rounding::NearestEven;
  constexpr Normalizer Nw = Normalizer::Newton, Rc = Normalizer::Recurrence;
  using std::integral_constant;
  const bool narrow = cfg.value_bits + cfg.interp_frac_bits + 2 <= 64;
  const int r = cfg.rounding == T ? 0 : cfg.rounding == N ? 1 : 2;
  const int key = r * 4 + (cfg.shading_normalizer == Nw ? 0 : 2) + (narrow ? 0 : 1);
  using RT = integral_constant<Rounding, T>;
  using RN = integral_constant<Rounding, N>;
  using RE = integral_constant<Rounding, E>;
  using ZN = integral_constant<Normalizer, Nw>;
  using ZR = integral_constant<Normalizer, Rc>;
  using W1 = std::true_type;
  using W0 = std::false_type;
  switch (key) {
    case 0: return f(RT{}, ZN{}, W1{});
    case 1: return f(RT{}, ZN{}, W0{});
    case 2: return f(RT{}, ZR{}, W1{});
    case 3: return f(RT{}, ZR{}, W0{});
    case 4: return f(RN{}, ZN{}, W1{});
    case 5: return f(RN{}, ZN{}, W0{});
    case 6: return f(RN{}, ZR{}, W1{});
    case 7: return f(RN{}, ZR{}, W0{});
    case 8: return f(RE{}, ZN{}, W1{});
    case 9: return f(RE{}, ZN{}, W0{});
    case 10: return f(RE{}, ZR{}, W1{});
    default: return f(RE{}, ZR{}, W0{});
  }
}

}  // namespace

// shadeSpan and shadePixel (shading_arithmetic.h) live here, beside the datapath they
// dispatch to: one switch a call.
// A pixel is a span of one (the depth within the 64-bit datapath's depth_bits <= 40 fits
// the record's 48 bits).
std::array<std::uint8_t, 3> shadePixel(const PrimitiveSetup& s, const LightingSetup& L, const HwConfig& cfg, int u, int v,
                                       i128 z, int cap, OverflowCounter& ovf) {
  if (!shadingDatapath64Applies(cfg)) return shadePixelWide(s, L, cfg, u, v, z, cap);
  ZEntry e;
  e.set(z, 0, 0, cap);
  std::array<std::uint8_t, 3> rgb;
  shadeSpan(s, L, cfg, u, v, 1, &e, &rgb, ovf);
  return rgb;
}

void shadeSpan(const PrimitiveSetup& s, const LightingSetup& L, const HwConfig& cfg, int u, int v, int n,
               const ZEntry* winners, std::array<std::uint8_t, 3>* rgb, OverflowCounter& ovf) {
  (void)ovf;  // colours above white clamp by design (as in every renderer), not an overflow
  if (!shadingDatapath64Applies(cfg)) {
    for (int i = 0; i < n; ++i) rgb[i] = shadePixelWide(s, L, cfg, u + i, v, winners[i].depth, int(winners[i].cap));
    return;
  }
  dispatch64(cfg, [&](auto r, auto z, auto w) {
    shadeSpan64<decltype(r)::value, decltype(z)::value, decltype(w)::value>(s, L, cfg, u, v, n, winners, rgb);
  });
}

}  // namespace qacc
