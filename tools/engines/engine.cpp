#include "tools/engines/engine.h"

#include <chrono>
#include <stdexcept>

#include "modeling/scene/scene_error.h"
#include "raster/reference/reference_renderer.h"
#include "tools/engines/facet_engine.h"
#include "tools/engines/hw_engine.h"

namespace qacc {

std::vector<std::string> engineNames() {
  std::vector<std::string> names{"reference"};
  for (const auto& n : hwEngineNames()) names.push_back(n);
  names.push_back("facets");
  return names;
}

void requireCsgSupport(const std::string& engine, const Scene& scene) {
  if (scene.csg_trees.empty() || engine == "reference" || engine == "hw" || engine == "hw-cycle") return;
  throw SceneError(scene.file, "/objects/" + std::to_string(scene.csg_trees.front().object),
                   "engine '" + engine + "' cannot draw 'csg' objects yet (use --engine reference)");
}

EngineResult runEngine(const std::string& engine, const Scene& scene, const EngineOptions& options) {
  EngineResult r;
  const auto t0 = std::chrono::steady_clock::now();
  if (engine == "reference") {
    ReferenceStats st;
    r.fb = renderReference(scene, options.threads, &st);
    r.host_ms = std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - t0).count();
    r.notes.push_back("reference: setup " + std::to_string(st.setup_ms) + " ms, visibility " +
                      std::to_string(st.visibility_ms) + " ms, shading " + std::to_string(st.shading_ms) +
                      " ms, " + std::to_string(st.pixel_tests) + " pixel tests");
    return r;
  }
  requireCsgSupport(engine, scene);
  if (runHwEngine(engine, scene, options, r)) return r;
  if (runFacetEngine(engine, scene, options, r)) return r;
  // --- further engines (hw, hw-cycle, facets) are dispatched above this line ---
  std::string names;
  for (const auto& n : engineNames()) names += (names.empty() ? "" : ", ") + n;
  throw std::invalid_argument("unknown engine '" + engine + "' (available: " + names + ")");
}

}  // namespace qacc
