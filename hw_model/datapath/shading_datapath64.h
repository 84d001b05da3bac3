// The shading datapath of shading_arithmetic.h computed with 64-bit host registers — the
// same bits as the 128-bit reference (shadePixelWide), for less host work; shadePixel
// takes it wherever it applies. What differs from the reference, and why the bits are the same:
//  - the normaliser keeps every register in 64 bits (vector_normalizer64.h gives the bounds)
//    and takes the Newton step as one 64 x 64 -> 128-bit multiply (ReciprocalSqrt::compute64);
//  - the lights come regrouped by type and each material's ambient term summed
//    (LightingSetup::directional64, points64, materials64): a pixel's colour is a sum of
//    integers, the same in any order;
//  - the rounding shifts of dot products and colour terms test no overflow: |N_k|, |V_k|,
//    |H_k| <= 2^uf + 2 (unit vectors, rounded) and light directions < 2^(uf+1), so a dot
//    product's sum is below 3 · 2^(2uf+2) <= 3 · 2^42; the diffuse product colour · (N·L) is at most
//    2^(cf+uf) <= 2^36, and a colour term light · (diffuse + specular) at most
//    2^(cf+7) · (2^cf + 2^31) < 2^56 (the specular ROM holds 32-bit entries).
#pragma once
#include <array>
#include <cstdint>

#include "hw_model/config/hw_config.h"
#include "hw_model/datapath/primitive_setup.h"
#include "hw_model/datapath/shading_arithmetic.h"

namespace qacc {

// Whether the 64-bit datapath holds every register of cfg's shading unit: always with the
// Newton normaliser (normal_bits <= 30); with the recurrence, up to normal_bits 23
// (len2 · 2^16 < 2^63).
inline bool shadingDatapath64Applies(const HwConfig& cfg) {
  return cfg.shading_normalizer == Normalizer::Newton || cfg.normal_bits <= 23;
}

// shadePixel (declared in shading_arithmetic.h, defined in shading_datapath64.cpp) takes
// this datapath when it applies and shadePixelWide otherwise.

}  // namespace qacc
