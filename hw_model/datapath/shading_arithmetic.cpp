#include "hw_model/datapath/shading_arithmetic.h"

#include <algorithm>
#include <cmath>

#include "hw_model/datapath/reciprocal_sqrt.h"
#include "hw_model/datapath/shading_field.h"
#include "hw_model/datapath/sqrt_extractor.h"
#include "raster/pixel/shading.h"

namespace qacc {

LightingSetup LightingSetup::build(const Scene& scene, const HwConfig& cfg, OverflowCounter& ovf) {
  LightingSetup L;
  const int cf = cfg.color_frac_bits, uf = cfg.unit_frac_bits;
  int point = 0;
  for (const Light& l : scene.lights) {
    LightQ q;
    q.type = l.type;
    for (int k = 0; k < 3; ++k) q.color[k] = quantize(std::max(0.0, l.color[k]), cf, cf + 8, cfg.overflow, ovf);
    if (l.type == Light::Type::Directional) {
      const Eigen::Vector3d d = -l.direction.normalized();
      for (int k = 0; k < 3; ++k) q.dir[k] = quantize(d[k], uf, uf + 2, cfg.overflow, ovf);
    } else if (l.type == Light::Type::Point) {
      q.point = point++;
    }
    L.lights.push_back(q);
  }
  std::vector<Material> mats = scene.materials;
  if (mats.empty()) mats.emplace_back();
  // A material no primitive uses gets no specular ROM (2^unit_frac_bits + 1 powers each):
  // the host spends nothing on what the scene does not draw.
  std::vector<char> used(mats.size(), 0);
  for (const Primitive& p : scene.primitives)
    if (p.material >= 0 && std::size_t(p.material) < used.size()) used[std::size_t(p.material)] = 1;
  std::vector<OverflowCounter> romEvents(mats.size());  // what each material's ROM counted
  for (std::size_t mi = 0; mi < mats.size(); ++mi) {
    const Material& m = mats[mi];
    MaterialQ q;
    for (int k = 0; k < 3; ++k) q.color[k] = quantize(std::clamp(m.color[k], 0.0, 1.0), cf, cf + 2, cfg.overflow, ovf);
    if (!used[mi]) {
      L.materials.push_back(std::move(q));
      continue;
    }
    // Materials with the same specular weight and shininess have the same ROM: built once
    // and shared on the host (each material still counts the quantisation events of its
    // ROM, as building it again would).
    bool shared = false;
    for (std::size_t j = 0; j < mi && !shared; ++j)
      if (used[j] && mats[j].specular == m.specular && mats[j].shininess == m.shininess) {
        q.specular = L.materials[j].specular;
        ovf.events += romEvents[j].events;
        ovf.zeroed += romEvents[j].zeroed;
        ovf.coarse += romEvents[j].coarse;
        romEvents[mi] = romEvents[j];
        shared = true;
      }
    if (shared) {
      L.materials.push_back(std::move(q));
      continue;
    }
    const int n = (1 << uf) + 1;
    auto table = std::make_shared<std::vector<std::int32_t>>(std::size_t(n));
    // Entries saturate at the ROM's 32-bit width, counted as shading overflows (a specular
    // weight above about 5e5 wrapped to negative values before: a 13 dB image, said nowhere).
    OverflowCounter& rom = romEvents[mi];
    for (int i = 0; i < n; ++i)
      (*table)[std::size_t(i)] = std::int32_t(
          quantize(m.specular * std::pow(std::ldexp(double(i), -uf), m.shininess), cf, 32, OverflowMode::Saturate, rom));
    q.specular = std::move(table);
    ovf.events += rom.events;
    ovf.zeroed += rom.zeroed;
    ovf.coarse += rom.coarse;
    L.materials.push_back(std::move(q));
  }
  for (const LightQ& q : L.lights) {
    if (q.type == Light::Type::Directional) {
      Directional64 d;
      for (int k = 0; k < 3; ++k) d.color[k] = std::int64_t(q.color[k]), d.dir[k] = std::int64_t(q.dir[k]);
      L.directional64.push_back(d);
    } else if (q.type == Light::Type::Point) {
      Point64 p;
      for (int k = 0; k < 3; ++k) p.color[k] = std::int64_t(q.color[k]);
      p.point = q.point;
      L.points64.push_back(p);
    }
  }
  for (const MaterialQ& q : L.materials) {
    Material64 m;
    for (int k = 0; k < 3; ++k) m.color[k] = std::int64_t(q.color[k]);
    for (const LightQ& l : L.lights)
      if (l.type == Light::Type::Ambient)
        for (int k = 0; k < 3; ++k) m.ambient[k] += std::int64_t(shiftRound(l.color[k] * q.color[k], cf, cfg.rounding));
    m.specular = q.specular ? q.specular->data() : nullptr;
    L.materials64.push_back(m);
  }
  const int ns = (1 << cf) + 1;
  L.srgb.resize(std::size_t(ns));
  for (int i = 0; i < ns; ++i) L.srgb[std::size_t(i)] = linearToSrgb8(std::ldexp(double(i), -cf));
  return L;
}

namespace {

// The reference datapath: the shading unit as specified, with 128-bit registers throughout
// (shadePixelWide). shadePixel computes the same bits with 64-bit registers
// (shading_datapath64.h) wherever they provably hold every value; tests compare the two.

using T = i128;

// Inlined into the shading datapath (four calls a pixel): its inputs then stay in registers
// instead of being stored as 64-bit halves and reloaded as 128-bit values.
template <Rounding R>
[[gnu::always_inline]] inline void normalizeT(const i128 in[3], const HwConfig& cfg, T out[3]) {
  const int nb = cfg.normal_bits, uf = cfg.unit_frac_bits, G = 8;
  T n[3];
  // The leading-zero normaliser: the longest component's bit length, from the OR of the
  // magnitudes (the same length as the longest of the three).
  const unsigned __int128 m = magnitude(in[0]) | magnitude(in[1]) | magnitude(in[2]);
  if (m == 0) {
    out[0] = out[1] = out[2] = 0;
    return;
  }
  const int shift = bitLength(m) - (nb - 1);
  for (int k = 0; k < 3; ++k) n[k] = shiftRoundR<R, T>(in[k], shift);
  const T len2 = n[0] * n[0] + n[1] * n[1] + n[2] * n[2];
  if (cfg.shading_normalizer == Normalizer::Newton) {
    // unit = n / sqrt(len2) in 1.uf, with 1/sqrt(len2) = y · 2^-(2P+1+k) from the rsqrt unit.
    const ReciprocalSqrt::Result r = ReciprocalSqrt::compute((unsigned __int128)len2);
    const int sh = r.k + 2 * ReciprocalSqrt::kPrecision + 1 - uf;
    for (int k = 0; k < 3; ++k) out[k] = shiftRoundR<R, T>(n[k] * T(r.y), sh);
    return;
  }
  // Reciprocal square root by recurrence: R = 2^(uf + G + nb - 1) / sqrt(len2 · 2^2G), then unit = n R >> (nb - 1).
  const T root = T(SqrtExtractor::compute((unsigned __int128)(len2 * (T(1) << (2 * G)))));
  if (root == 0) {
    out[0] = out[1] = out[2] = 0;
    return;
  }
  const T rs = T(divRound(i128(1) << (uf + G + nb - 1), root, R));
  for (int k = 0; k < 3; ++k) out[k] = shiftRoundR<R, T>(n[k] * rs, nb - 1);
}

template <Rounding R>
inline T dot(const T a[3], const T b[3], int uf) {
  return shiftRoundR<R, T>(a[0] * b[0] + a[1] * b[1] + a[2] * b[2], uf);
}

template <Rounding R>
std::array<std::uint8_t, 3> shadeT(const PrimitiveSetup& s, const LightingSetup& L, const HwConfig& cfg, int u,
                                   int v, i128 z, int cap) {
  const int Fz = cfg.depth_frac_bits, uf = cfg.unit_frac_bits, cf = cfg.color_frac_bits;
  i128 raw[3];
  T N[3], V[3];
  if (cap >= 0) {
    for (int k = 0; k < 3; ++k) raw[k] = s.planes[std::size_t(cap)].capNormal[k];
  } else {
    for (int k = 0; k < 3; ++k) raw[k] = evalShadingField<false>(s.normal, k, u, v, z, Fz);
  }
  normalizeT<R>(raw, cfg, N);
  for (int k = 0; k < 3; ++k) raw[k] = evalShadingField<false>(s.view, k, u, v, z, Fz);
  normalizeT<R>(raw, cfg, V);
  if (dot<R>(N, V, uf) < 0)
    for (int k = 0; k < 3; ++k) N[k] = -N[k];  // two-sided
  const int mi = s.material >= 0 && s.material < int(L.materials.size()) ? s.material : 0;
  const LightingSetup::MaterialQ& m = L.materials[std::size_t(mi)];
  const T one = T(1) << uf;
  T out[3] = {0, 0, 0};
  for (const LightingSetup::LightQ& l : L.lights) {
    if (l.type == Light::Type::Ambient) {
      for (int k = 0; k < 3; ++k) out[k] += shiftRoundR<R, T>(T(l.color[k]) * T(m.color[k]), cf);
      continue;
    }
    T Lv[3];
    if (l.type == Light::Type::Directional) {
      for (int k = 0; k < 3; ++k) Lv[k] = T(l.dir[k]);
    } else {
      for (int k = 0; k < 3; ++k) raw[k] = evalShadingField<false>(s.pointLights[std::size_t(l.point)], k, u, v, z, Fz);
      normalizeT<R>(raw, cfg, Lv);
    }
    const T ndl = std::min(dot<R>(N, Lv, uf), one);
    if (ndl <= 0) continue;
    T H[3];
    i128 hs[3];
    for (int k = 0; k < 3; ++k) hs[k] = i128(Lv[k]) + i128(V[k]);
    normalizeT<R>(hs, cfg, H);
    const T ndh = std::clamp<T>(dot<R>(N, H, uf), 0, one);
    const T spec = (*m.specular)[std::size_t(ndh)];
    for (int k = 0; k < 3; ++k)
      out[k] += shiftRoundR<R, T>(T(l.color[k]) * (shiftRoundR<R, T>(T(m.color[k]) * ndl, uf) + spec), cf);
  }
  std::array<std::uint8_t, 3> rgb;
  const T top = T(1) << cf;
  for (int k = 0; k < 3; ++k) rgb[std::size_t(k)] = L.srgb[std::size_t(std::clamp<T>(out[k], 0, top))];
  return rgb;
}

// shadeT instantiated for the configured rounding mode.
std::array<std::uint8_t, 3> shadeRounded(const PrimitiveSetup& s, const LightingSetup& L, const HwConfig& cfg, int u, int v,
                                         i128 z, int cap) {
  switch (cfg.rounding) {
    case Rounding::Truncate: return shadeT<Rounding::Truncate>(s, L, cfg, u, v, z, cap);
    case Rounding::Nearest: return shadeT<Rounding::Nearest>(s, L, cfg, u, v, z, cap);
    case Rounding::NearestEven: break;
  }
  return shadeT<Rounding::NearestEven>(s, L, cfg, u, v, z, cap);
}

}  // namespace

// shadePixel: in shading_datapath64.cpp, beside the 64-bit datapath it takes where it applies.

std::array<std::uint8_t, 3> shadePixelWide(const PrimitiveSetup& s, const LightingSetup& L, const HwConfig& cfg, int u,
                                           int v, i128 z, int cap) {
  return shadeRounded(s, L, cfg, u, v, z, cap);
}

}  // namespace qacc
