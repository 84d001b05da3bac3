#include "hw_model/report/scene_needs.h"

#include <algorithm>

namespace qacc {

SceneNeeds SceneNeeds::of(const Scene& scene) {
  SceneNeeds n;
  for (const Primitive& p : scene.primitives) {
    const bool facet = p.isPlanar() && !p.solid;
    n.facets = n.facets || facet;
    n.solids = n.solids || (p.solid && !facet);
    n.max_planes = std::max(n.max_planes, int(p.clip.size()));
  }
  return n;
}

std::string SceneNeeds::describe() const {
  return std::string(solids ? "solids" : "no solids") + ", " + (facets ? "facets" : "no facets") + ", at most " +
         std::to_string(max_planes) + " clip plane" + (max_planes == 1 ? "" : "s") + " per primitive";
}

}  // namespace qacc
