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
  // Visible depths raised to the primitive's depth floor (PrimitiveSetup::zFloor): the
  // datapath returned a depth nearer than the piece's exact minimum less the margin.
  std::uint64_t depth_floor_clamps = 0;
  void add(const OverflowCounters& o) {
    OverflowCounter* mine[] = {&setup, &interpolator, &sqrt, &depth, &clip, &shading};
    const OverflowCounter* theirs[] = {&o.setup, &o.interpolator, &o.sqrt, &o.depth, &o.clip, &o.shading};
    for (int i = 0; i < 6; ++i) {
      mine[i]->events += theirs[i]->events;
      mine[i]->zeroed += theirs[i]->zeroed;
      mine[i]->coarse += theirs[i]->coarse;
    }
    depth_clamps += o.depth_clamps;
    depth_floor_clamps += o.depth_floor_clamps;
  }
  std::uint64_t total() const {
    return setup.events + interpolator.events + sqrt.events + depth.events + clip.events + shading.events;
  }
};

}  // namespace qacc
