#include "tools/engines/render_job.h"

#include <memory>

#include "modeling/loader/scene_loader.h"
#include "raster/image/pfm_io.h"
#include "raster/image/png_io.h"
#include "tools/engines/hw_engine.h"
#include "tools/engines/image_size.h"
#include "tools/engines/reference_cache.h"

namespace qacc {

RenderJobResult runRenderJob(const RenderJob& job) {
  RenderJobResult out;
  if (!job.options.report_accuracy) {
    bool hw = false;
    for (const auto& n : hwEngineNames()) hw |= n == job.engine;
    if (!hw)
      throw std::invalid_argument("--no-accuracy applies to the accelerator engines only (engine '" + job.engine +
                                  "' prints no accuracy line)");
  }
  const bool accuracy = job.options.report_accuracy && job.engine != "reference";
  if (!accuracy && (!job.use_cache || !job.cache_dir.empty()))
    throw std::invalid_argument(std::string(job.use_cache ? "--cache" : "--no-cache") +
                                " applies to the accuracy line's reference, which " +
                                (job.engine == "reference" ? "the reference engine does not print"
                                                           : "--no-accuracy turns off"));
  checkImageSize(job.width, job.height);
  out.scene = loadScene(job.scene_path, job.options.limits, ViewCulling{job.view_cull, job.width, job.height});
  applyImageSize(out.scene, job.width, job.height);
  EngineOptions options = job.options;
  std::unique_ptr<ReferenceCache> cache;
  std::string cacheKey;
  if (accuracy && job.use_cache) {
    cache = std::make_unique<ReferenceCache>(job.cache_dir);
    const std::string text = readSceneText(job.scene_path, job.options.limits);
    const std::string dir = sceneDirectory(job.scene_path);
    cacheKey = ReferenceCache::key(text, dir, out.scene.width, out.scene.height);
    options.accuracy_reference = [&cache, text, dir, threads = job.options.threads](const Scene& s) {
      return cache->get(text, dir, s.width, s.height, [&s] { return s; }, threads, /*primitiveIds=*/false);
    };
  }
  out.result = runEngine(job.engine, out.scene, options);
  if (cache)
    out.result.notes.push_back(std::string("accuracy reference: ") +
                               (cache->hits() > 0 ? "read from" : "rendered into") + " the reference cache, " +
                               cache->directory() + "/" + cacheKey + ".frame");
  const FrameBuffer& fb = out.result.fb;
  if (!job.color_path.empty()) writePng(job.color_path, fb.color);
  if (!job.ids_path.empty()) writePng16(job.ids_path, fb.idImage());
  if (!job.depth_path.empty()) writePfm(job.depth_path, fb.depthImage());
  return out;
}

}  // namespace qacc
