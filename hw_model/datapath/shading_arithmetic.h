// Shading arithmetic: design §2 lighting in fixed point (ambient + Lambert + Blinn-Phong per
// light, two-sided, material colour, 8-bit sRGB out), per visible pixel:
//  - the normal N, the view vector V and point-light vectors L are affine fields in
//    (u, v, z) (setup: PrimitiveSetup::normal/view/pointLights; a cap uses its plane's
//    normal), evaluated exactly, then normalised: a leading-zero shift to normal_bits,
//    then a reciprocal square root (seed ROM + Newton step, reciprocal_sqrt.h; or, with
//    shading_normalizer = "recurrence", the digit-recurrence square root and a divider)
//    and three multiplies → unit vectors in 1.unit_frac;
//  - dot products in 1.unit_frac; the specular power comes from a per-material table
//    (ROM) indexed by N·H; colours in 0.color_frac; the sRGB transfer is a table indexed
//    by the linear colour (color_frac bits).
#pragma once
#include <array>
#include <cstdint>
#include <memory>
#include <vector>

#include "hw_model/config/hw_config.h"
#include "hw_model/datapath/primitive_setup.h"
#include "hw_model/datapath/zbuffer_memory.h"
#include "modeling/scene/scene.h"

namespace qacc {

// Per-scene lighting constants in the shading formats.
struct LightingSetup {
  struct LightQ {
    Light::Type type = Light::Type::Ambient;
    i128 color[3] = {0, 0, 0};  // 0.color_frac
    i128 dir[3] = {0, 0, 0};    // directional: unit vector towards the light (1.unit_frac)
    int point = -1;             // point light: index into PrimitiveSetup::pointLights
  };
  struct MaterialQ {
    i128 color[3] = {0, 0, 0};
    // ROM: specular · (i / 2^unit_frac)^shininess, 0.color_frac; null for a material no
    // primitive uses (never read). Materials with the same specular weight and shininess
    // share one table on the host (one copy in the host's caches).
    std::shared_ptr<const std::vector<std::int32_t>> specular;
  };
  std::vector<LightQ> lights;
  std::vector<MaterialQ> materials;
  std::vector<std::uint8_t> srgb;  // ROM: linear i / 2^color_frac → 8-bit sRGB

  // The same constants regrouped for the 64-bit datapath (shading_datapath64.h), each a
  // 64-bit value (light colours below 2^(color_frac+7), material colours at most
  // 2^color_frac, directions below 2^(unit_frac+1) in magnitude): the directional and the
  // point lights in two lists, and per material the sum of its ambient terms,
  // Σ round(light · colour · 2^-color_frac) over the ambient lights (in cfg.rounding). The
  // colour of a pixel is a sum of integer terms, the same in any order.
  struct Directional64 {
    std::int64_t color[3] = {0, 0, 0}, dir[3] = {0, 0, 0};
  };
  struct Point64 {
    std::int64_t color[3] = {0, 0, 0};
    int point = 0;  // index into PrimitiveSetup::pointLights
  };
  struct Material64 {
    std::int64_t color[3] = {0, 0, 0}, ambient[3] = {0, 0, 0};
    const std::int32_t* specular = nullptr;  // the entries of MaterialQ::specular (kept alive by it)
  };
  std::vector<Directional64> directional64;
  std::vector<Point64> points64;
  std::vector<Material64> materials64;
  // Values that do not fit their formats (light colours of 2^8 and more, specular table
  // entries of 2^(31 - color_frac) and more) saturate and are counted in `ovf`.
  static LightingSetup build(const Scene& scene, const HwConfig& cfg, OverflowCounter& ovf);
};

// The colour of a visible point (u, v local to the primitive's box, z internal depth, cap
// plane or -1) in 8-bit sRGB. L must have been built with the same cfg.
std::array<std::uint8_t, 3> shadePixel(const PrimitiveSetup& s, const LightingSetup& L, const HwConfig& cfg, int u, int v,
                                       i128 z, int cap, OverflowCounter& ovf);
// The n winners of one primitive at (u, v), (u + 1, v), ... of a row (each record's depth
// and cap): rgb[i] is shadePixel(s, L, cfg, u + i, v, winners[i].depth, winners[i].cap, ovf),
// bit for bit, the shading fields' affine parts advanced along the row by forward
// differences, as a shading unit fed a span would (shading_datapath64.cpp).
void shadeSpan(const PrimitiveSetup& s, const LightingSetup& L, const HwConfig& cfg, int u, int v, int n,
               const ZEntry* winners, std::array<std::uint8_t, 3>* rgb, OverflowCounter& ovf);
// The reference: the same datapath with 128-bit registers throughout, computed as specified
// (shadePixel uses 64-bit registers and the regrouped constants where the widths allow,
// shading_datapath64.h; the two must agree bit for bit).
std::array<std::uint8_t, 3> shadePixelWide(const PrimitiveSetup& s, const LightingSetup& L, const HwConfig& cfg, int u,
                                           int v, i128 z, int cap);

}  // namespace qacc
