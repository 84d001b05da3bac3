// OverflowCounters: overflow events per datapath (a value that did not fit its register:
// saturated or wrapped, never silent), and clamps (depths beyond the depth datapath's
// range, which are outside the view volume by construction and are clamped by design).
#pragma once
#include <cstdint>

#include "hw_model/datapath/fixed_point.h"

namespace qacc {

struct OverflowCounters {
  OverflowCounter setup, interpolator, sqrt, depth, clip, shading;
  std::uint64_t depth_clamps = 0;
  void add(const OverflowCounters& o) {
    setup.events += o.setup.events;
    interpolator.events += o.interpolator.events;
    sqrt.events += o.sqrt.events;
    depth.events += o.depth.events;
    clip.events += o.clip.events;
    shading.events += o.shading.events;
    depth_clamps += o.depth_clamps;
  }
  std::uint64_t total() const {
    return setup.events + interpolator.events + sqrt.events + depth.events + clip.events + shading.events;
  }
};

}  // namespace qacc
