// Engine dispatch for `qacc render --engine NAME` and the commands that render
// (batch, bench, compare). Each engine renders a Scene into a FrameBuffer and says what
// it measured. Engines are added here, one branch each.
#pragma once
#include <functional>
#include <string>
#include <vector>

#include "modeling/scene/scene.h"
#include "modeling/support/limits.h"
#include "raster/image/frame_buffer.h"

namespace qacc {

struct EngineOptions {
  int threads = 0;          // <= 0: OpenMP default
  std::string config_path;  // accelerator configuration JSON (hw, hw-cycle)
  std::string stats_path;   // statistics JSON (+ CSV alongside), every engine
  int level = 0;            // tessellation level (facets)
  std::string shading;      // facet shading mode (facets)
  bool report_accuracy = true;  // hw, hw-cycle, facets: compare with the reference after rendering
  // Where the accuracy line's reference frame comes from: empty renders it
  // (renderReference); `render` and `batch` serve it from the ReferenceCache, without its
  // primitive ids (the accuracy metrics read colour, depth and objects).
  std::function<FrameBuffer(const Scene&)> accuracy_reference;
  Limits limits;            // loading and tessellation bounds (--max-*)
};

struct EngineResult {
  FrameBuffer fb;
  double host_ms = 0;             // wall time of the render itself
  std::vector<std::string> notes; // lines the engine wants printed (stats, accuracy...)
  std::string accuracy;           // hw engines: the accuracy line (also in notes), empty with --no-accuracy
};

// Refuses an unknown engine and every option the engine does not read (--config outside
// hw / hw-cycle, --level and --shading outside facets) with a message naming both.
void checkEngineOptions(const std::string& engine, const EngineOptions& options);
// Throws std::invalid_argument for an unknown engine or one not built in, or an option
// the engine does not read. `stats_path` works for every engine.
EngineResult runEngine(const std::string& engine, const Scene& scene, const EngineOptions& options);
std::vector<std::string> engineNames();
// Throws a SceneError naming the first `csg` object when `engine` cannot draw CSG (every
// engine but the reference): drawing the leaves one by one would be a silently wrong image.
void requireCsgSupport(const std::string& engine, const Scene& scene);
// The reference frame the accuracy line compares with: options.accuracy_reference when
// set, else a fresh renderReference.
FrameBuffer accuracyReferenceFrame(const Scene& scene, const EngineOptions& options);

}  // namespace qacc
