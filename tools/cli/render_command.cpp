// qacc render SCENE -o out.png [--engine ...] [--width W --height H] [--ids ids.png]
//             [--depth depth.pfm] [--stats stats.json] [--config hw.json] [--level N]
//             [--threads N] [--no-accuracy] [--cache DIR | --no-cache]
#include <cstdio>
#include <memory>

#include "tools/cli/commands.h"
#include "tools/cli/limit_options.h"
#include "tools/cli/reference_cache_options.h"
#include "tools/cli/threads_option.h"
#include "tools/cli/view_cull_option.h"
#include "tools/engines/render_job.h"

namespace qacc {

void addRenderCommand(CLI::App& app) {
  auto job = std::make_shared<RenderJob>();
  CLI::App* cmd = app.add_subcommand("render", "Render a scene to PNG");
  cmd->add_option("scene", job->scene_path, "Scene file (qacc-scene/1 JSON)")->required();
  cmd->add_option("-o,--output", job->color_path, "Colour PNG to write")->required();
  std::string engines;
  for (const auto& n : engineNames()) engines += (engines.empty() ? "" : "|") + n;
  cmd->add_option("--engine", job->engine, "Renderer: " + engines)->capture_default_str();
  cmd->add_option("--width", job->width, "Image width (overrides the scene; with --height)");
  cmd->add_option("--height", job->height, "Image height (overrides the scene; with --width)");
  cmd->add_option("--ids", job->ids_path, "16-bit PNG of object index + 1 per pixel (0 = nothing)");
  cmd->add_option("--depth", job->depth_path, "PFM of window depth (+inf where nothing was hit)");
  cmd->add_option("--stats", job->options.stats_path, "Accelerator statistics JSON (CSV alongside)");
  cmd->add_option("--config", job->options.config_path, "Accelerator configuration JSON");
  cmd->add_option("--level", job->options.level, "Tessellation level (facets engine; 2 or more)")
      ->check(CLI::Range(2, 1000000));
  cmd->add_option("--shading", job->options.shading, "Facet shading: gouraud|pixel (facets engine)");
  cmd->add_flag("!--no-accuracy", job->options.report_accuracy,
                "hw engines: skip the accuracy line (no reference render)");
  addReferenceCacheOptions(cmd, job->use_cache, job->cache_dir);
  addThreadsOption(cmd, job->options.threads);
  addLimitOptions(cmd, job->options.limits);
  addViewCullOption(cmd, job->view_cull);
  cmd->callback([job] {
    const RenderJobResult r = runRenderJob(*job);
    const Scene& s = r.scene;
    std::printf("%s: %zu primitives, %dx%d, engine %s, %zu pixels covered, %.2f ms\n", s.name.c_str(),
                s.primitives.size(), s.width, s.height, job->engine.c_str(), r.result.fb.covered(),
                r.result.host_ms);
    for (const auto& line : r.result.notes) std::printf("  %s\n", line.c_str());
  });
}

}  // namespace qacc
