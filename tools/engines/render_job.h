// RenderJob: load a scene, optionally resize it, render it with an engine and write the
// requested outputs (colour PNG, 16-bit id PNG, PFM depth). Shared by `render` and `batch`.
#pragma once
#include <string>

#include "tools/engines/engine.h"

namespace qacc {

struct RenderJob {
  std::string scene_path;
  std::string engine = "reference";
  int width = 0, height = 0;  // 0: the scene's own size (image_size.h)
  bool view_cull = true;      // the loader's view culling at that size (modeling/loader/view_culling.h)
  std::string color_path;     // empty: not written
  std::string ids_path;
  std::string depth_path;
  EngineOptions options;
  // The accuracy line's reference (hw engines, facets) comes from the ReferenceCache
  // (tools/engines/reference_cache.h): rendered once per scene content, size and
  // reference version, then read back. cache_dir empty: $QACC_CACHE or ~/.cache/qacc.
  bool use_cache = true;
  std::string cache_dir;
};

struct RenderJobResult {
  Scene scene;
  EngineResult result;
};

// Throws SceneError for bad scenes, std::invalid_argument for bad options.
RenderJobResult runRenderJob(const RenderJob& job);

}  // namespace qacc
