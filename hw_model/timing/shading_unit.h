// ShadingUnit: design §2 lighting in fixed point (ambient + Lambert + Blinn-Phong per
// light, two-sided, material colour, 8-bit sRGB out), per visible pixel:
//  - the normal N, the view vector V and point-light vectors L are affine fields in
//    (u, v, z) (setup: PrimitiveSetup::normal/view/pointLights; a cap uses its plane's
//    normal), evaluated exactly, then normalised: a leading-zero shift to normal_bits,
//    then a reciprocal square root (seed ROM + Newton step, rsqrt_unit.h; or, with
//    shading_normalizer = "recurrence", the digit-recurrence square root and a divider)
//    and three multiplies → unit vectors in 1.unit_frac;
//  - dot products in 1.unit_frac; the specular power comes from a per-material table
//    (ROM) indexed by N·H; colours in 0.color_frac; the sRGB transfer is a table indexed
//    by the linear colour (color_frac bits).
#pragma once
#include <array>
#include <cstdint>
#include <vector>

#include "hw_model/timing/delay_queue.h"
#include "hw_model/timing/fifo.h"
#include "hw_model/config/hw_config.h"
#include "hw_model/datapath/primitive_setup.h"
#include "hw_model/timing/unit.h"
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
    std::vector<std::int32_t> specular;  // ROM: specular · (i / 2^unit_frac)^shininess, 0.color_frac
  };
  std::vector<LightQ> lights;
  std::vector<MaterialQ> materials;
  std::vector<std::uint8_t> srgb;  // ROM: linear i / 2^color_frac → 8-bit sRGB
  static LightingSetup build(const Scene& scene, const HwConfig& cfg);
};

// A pixel that passed the Z test, on its way to shading.
struct ShadeRequest {
  int prim = 0;
  int x = 0, y = 0;
  int cap = -1;
  i128 z = 0;
};

class ShadingUnit : public Unit {
 public:
  static std::array<std::uint8_t, 3> shade(const PrimitiveSetup& s, const LightingSetup& L, const HwConfig& cfg,
                                           int u, int v, i128 z, int cap, OverflowCounter& ovf);
  // The same datapath with 128-bit registers throughout (shade() uses 64-bit registers
  // where the widths allow; the two must agree bit for bit).
  static std::array<std::uint8_t, 3> shadeWide(const PrimitiveSetup& s, const LightingSetup& L, const HwConfig& cfg,
                                               int u, int v, i128 z, int cap);

  // Timing: pipelined, one pixel every shading_cycles_per_pixel, shading_latency deep;
  // the colour is written to the frame buffer when the pixel leaves the unit.
  using Writer = void (*)(void* ctx, const ShadeRequest& r);
  ShadingUnit(const std::string& name, const HwConfig& cfg, Fifo<ShadeRequest>& in, Writer w, void* ctx)
      : Unit(name), cfg_(cfg), in_(in), writer_(w), ctx_(ctx) {}
  bool tick(std::uint64_t now) override;
  std::uint64_t nextEvent() const override;
  bool holdsWork() const override { return !inflight_.empty(); }

 private:
  const HwConfig& cfg_;
  Fifo<ShadeRequest>& in_;
  Writer writer_;
  void* ctx_;
  DelayQueue<std::pair<std::uint64_t, ShadeRequest>> inflight_;
  std::uint64_t nextAccept_ = 0;
};

}  // namespace qacc
