#include "tools/engines/render_job.h"

#include "modeling/loader/scene_loader.h"
#include "raster/image/pfm_io.h"
#include "raster/image/png_io.h"
#include "tools/engines/hw_engine.h"
#include "tools/engines/image_size.h"

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
  checkImageSize(job.width, job.height);
  out.scene = loadScene(job.scene_path, job.options.limits, ViewCulling{job.view_cull, job.width, job.height});
  applyImageSize(out.scene, job.width, job.height);
  out.result = runEngine(job.engine, out.scene, job.options);
  const FrameBuffer& fb = out.result.fb;
  if (!job.color_path.empty()) writePng(job.color_path, fb.color);
  if (!job.ids_path.empty()) writePng16(job.ids_path, fb.idImage());
  if (!job.depth_path.empty()) writePfm(job.depth_path, fb.depthImage());
  return out;
}

}  // namespace qacc
