#include "tools/engines/engine.h"

#include <chrono>
#include <stdexcept>

#include "modeling/scene/scene_error.h"
#include "hw_model/report/accuracy_report.h"
#include "hw_model/report/stats_file.h"
#include "raster/osmesa/osmesa_renderer.h"
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
  if (engine == "facets" && facetCsgAvailable()) return;
  throw SceneError(scene.file, "/objects/" + std::to_string(scene.csg_trees.front().object),
                   "engine '" + engine + "' cannot draw 'csg' objects (" +
                       (engine == "facets" ? std::string(facetCsgMissingMessage()) : std::string("use --engine reference")) + ")");
}

void checkEngineOptions(const std::string& engine, const EngineOptions& options) {
  bool known = false;
  for (const auto& n : engineNames()) known |= n == engine;
  if (!known) {
    std::string names;
    for (const auto& n : engineNames()) names += (names.empty() ? "" : ", ") + n;
    throw std::invalid_argument("unknown engine '" + engine + "' (available: " + names + ")");
  }
  bool hw = false;
  for (const auto& n : hwEngineNames()) hw |= n == engine;
  const bool facets = engine == "facets";
  if (!options.config_path.empty() && !hw)
    throw std::invalid_argument("--config is read by the accelerator engines (hw, hw-cycle) only, not by engine '" +
                                engine + "'");
  if (options.level != 0 && !facets)
    throw std::invalid_argument("--level is read by the facets engine only, not by engine '" + engine + "'");
  if (!options.shading.empty() && !facets)
    throw std::invalid_argument("--shading is read by the facets engine only, not by engine '" + engine + "'");
}

namespace {
// The statistics file of the engines that have no HwStats: what was rendered, how long it
// took, and (facets) the accuracy against the reference.
void writeRenderStats(const std::string& engine, const Scene& scene, const EngineOptions& options,
                      const EngineResult& r, const AccuracyReport* accuracy) {
  nlohmann::ordered_json j;
  j["format"] = "qacc-render-stats/1";
  j["engine"] = engine;
  j["scene"] = scene.name;
  j["width"] = scene.width;
  j["height"] = scene.height;
  j["threads"] = options.threads;
  j["host_seconds"] = r.host_ms / 1e3;
  j["pixels_covered"] = r.fb.covered();
  if (engine == "facets") j["level"] = options.level > 0 ? options.level : kDefaultFacetLevel;
  if (accuracy) {
    nlohmann::ordered_json a;
    for (const auto& [k, v] : accuracy->fields()) a[k] = jsonNumber(v);
    j["accuracy"] = a;
  }
  writeStatsFiles(options.stats_path, j);
}
}  // namespace

FrameBuffer accuracyReferenceFrame(const Scene& scene, const EngineOptions& options) {
  if (options.accuracy_reference) return options.accuracy_reference(scene);
  return renderReference(scene, options.threads);
}

EngineResult runEngine(const std::string& engine, const Scene& scene, const EngineOptions& options) {
  checkEngineOptions(engine, options);
  EngineResult r;
  const auto t0 = std::chrono::steady_clock::now();
  if (engine == "reference") {
    ReferenceStats st;
    r.fb = renderReference(scene, options.threads, &st);
    r.host_ms = std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - t0).count();
    r.notes.push_back("reference: setup " + std::to_string(st.setup_ms) + " ms, visibility and shading " +
                      std::to_string(st.visibility_ms) + " ms, " + std::to_string(st.pixel_tests) + " pixel tests");
    if (!options.stats_path.empty()) writeRenderStats(engine, scene, options, r, nullptr);
    return r;
  }
  requireCsgSupport(engine, scene);
  if (runHwEngine(engine, scene, options, r)) return r;
  if (runFacetEngine(engine, scene, options, r)) {
    AccuracyReport a;
    if (options.report_accuracy) {
      a = accuracyReport(accuracyReferenceFrame(scene, options), r.fb, scene.camera);
      r.notes.push_back(a.line());
    }
    if (!options.stats_path.empty()) writeRenderStats(engine, scene, options, r, options.report_accuracy ? &a : nullptr);
    return r;
  }
  throw std::invalid_argument("engine '" + engine + "' is listed but not dispatched");
}

}  // namespace qacc
