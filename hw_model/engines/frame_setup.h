// FrameSetup: the per-frame state both accelerator engines start from — the setup
// arithmetic's output for every primitive (PrimitiveSetup, computed once, in parallel, in
// scene order) and the quantised lighting.
#pragma once
#include <vector>

#include "hw_model/config/hw_config.h"
#include "hw_model/datapath/overflow_counters.h"
#include "hw_model/datapath/primitive_setup.h"
#include "hw_model/datapath/shading_arithmetic.h"
#include "modeling/scene/scene.h"

namespace qacc {

struct FrameSetup {
  std::vector<PrimitiveSetup> setups;
  LightingSetup lighting;
  OverflowCounters overflow;  // setup overflows
  double storedDepthStep = 0;  // window depth of one step of the stored Z (2^-zbuffer_bits)
  static FrameSetup build(const Scene& scene, const HwConfig& cfg, int threads);
};

}  // namespace qacc
