#include "tools/engines/render_job.h"

#include <stdexcept>

#include "modeling/loader/scene_loader.h"
#include "raster/image/pfm_io.h"
#include "raster/image/png_io.h"

namespace qacc {

RenderJobResult runRenderJob(const RenderJob& job) {
  RenderJobResult out;
  out.scene = loadScene(job.scene_path, job.options.limits);
  if ((job.width > 0) != (job.height > 0))
    throw std::invalid_argument("--width and --height go together");
  if (job.width > 0) {
    if (job.width > kMaxImageSide || job.height > kMaxImageSide ||
        (long long)job.width * job.height > kMaxImagePixels)
      throw std::invalid_argument("image size " + std::to_string(job.width) + "x" + std::to_string(job.height) +
                                  " is over the limit (" + std::to_string(kMaxImageSide) + " per side, " +
                                  std::to_string(kMaxImagePixels) + " pixels)");
    out.scene.width = job.width;
    out.scene.height = job.height;
  }
  out.result = runEngine(job.engine, out.scene, job.options);
  const FrameBuffer& fb = out.result.fb;
  if (!job.color_path.empty()) writePng(job.color_path, fb.color);
  if (!job.ids_path.empty()) writePng16(job.ids_path, fb.idImage());
  if (!job.depth_path.empty()) writePfm(job.depth_path, fb.depthImage());
  return out;
}

}  // namespace qacc
