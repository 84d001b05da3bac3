#include "tools/engines/hw_engine.h"

#include <chrono>
#include <stdexcept>
#include <string>

#include "hw_model/report/accuracy_report.h"
#include "hw_model/engines/cycle_engine.h"
#include "hw_model/engines/functional_engine.h"
#include "raster/reference/reference_renderer.h"

namespace qacc {

std::vector<std::string> hwEngineNames() { return {"hw", "hw-cycle"}; }

FrameBuffer renderWithHwEngine(const std::string& engine, const Scene& scene, const HwConfig& cfg, int threads,
                               HwStats& stats, DatapathReuse* reuse) {
  if (engine == "hw") {
    HwRender r = renderHw(scene, cfg, threads);
    stats = r.stats;
    return std::move(r.fb);
  }
  if (engine == "hw-cycle") {
    HwRender r = renderHwCycle(scene, cfg, threads, MachineClock::Items, reuse);
    stats = r.stats;
    return std::move(r.fb);
  }
  throw std::invalid_argument("not an accelerator engine: " + engine);
}

bool runHwEngine(const std::string& engine, const Scene& scene, const EngineOptions& options, EngineResult& out) {
  bool known = false;
  for (const auto& n : hwEngineNames()) known |= n == engine;
  if (!known) return false;
  const HwConfig cfg = options.config_path.empty() ? HwConfig() : loadHwConfig(options.config_path);
  const auto t0 = std::chrono::steady_clock::now();
  HwStats stats;
  out.fb = renderWithHwEngine(engine, scene, cfg, options.threads, stats);
  out.host_ms = std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - t0).count();
  for (const auto& l : stats.summaryLines()) out.notes.push_back(l);
  if (options.report_accuracy) {
    const FrameBuffer ref = accuracyReferenceFrame(scene, options);
    stats.accuracy = accuracyReport(ref, out.fb, scene.camera);
    stats.has_accuracy = true;
    out.accuracy = stats.accuracy.line();
    if (stats.csg.overflowed_pixels > 0)
      out.accuracy += "; " + std::to_string(stats.csg.overflowed_pixels) +
                      " pixels of csg objects overflowed their interval lists (csg_list_depth " +
                      std::to_string(cfg.csg_list_depth) + "; the nearest intervals kept): they may be wrong";
    out.notes.push_back(out.accuracy);
  }
  if (!options.stats_path.empty()) stats.write(options.stats_path);
  return true;
}

}  // namespace qacc
