// SceneNeeds: the units of the accelerator a scene uses — cap logic only for solids, as many
// clip evaluators as its largest plane count, the facet path only for facets. The cost model
// prices the configuration the scene needs beside the full one (CostModel::of(cfg, &needs));
// every hw render prints both (HwStats) and `--stats` writes both (`cost`, `cost_needed`).
#pragma once
#include <string>

#include "modeling/scene/scene.h"

namespace qacc {

struct SceneNeeds {
  bool solids = false;  // a solid quadric (cap logic and cap depths)
  bool facets = false;  // a planar, non-solid primitive (the facet path's depth interpolator)
  int max_planes = 0;   // the most clip planes of one primitive (clip evaluators)
  static SceneNeeds of(const Scene& scene);
  // "solids, facets, at most N clip planes" in words.
  std::string describe() const;
};

}  // namespace qacc
