// qacc batch SCENE... --out DIR [--engine E] [--threads N] [--width W --height H] [--no-accuracy]
//            [--cache DIR | --no-cache]
// Renders every scene into DIR/<scene file name>.png and prints a table (hw engines: each
// row followed by its accuracy line against the reference, unless --no-accuracy). A scene
// that cannot be rendered prints "qacc: error: ..." and the batch goes on with the next
// one; the command then fails (exit 1) naming how many scenes failed.
#include <cstdio>
#include <filesystem>
#include <memory>
#include <stdexcept>

#include "tools/cli/commands.h"
#include "tools/engines/image_size.h"
#include "tools/cli/limit_options.h"
#include "tools/cli/reference_cache_options.h"
#include "tools/cli/threads_option.h"
#include "tools/cli/view_cull_option.h"
#include "tools/engines/render_job.h"

namespace qacc {

namespace {
struct BatchArgs {
  std::vector<std::string> scenes;
  std::string out = "out";
  std::string engine = "reference";
  int threads = 0, width = 0, height = 0;
  bool accuracy = true;
  bool use_cache = true;
  std::string cache_dir;
  Limits limits;
  bool view_cull = true;
};
}  // namespace

void addBatchCommand(CLI::App& app) {
  auto args = std::make_shared<BatchArgs>();
  CLI::App* cmd = app.add_subcommand("batch", "Render several scenes into a directory and print a table");
  cmd->add_option("scenes", args->scenes, "Scene files")->required();
  cmd->add_option("--out", args->out, "Output directory")->capture_default_str();
  cmd->add_option("--engine", args->engine, "Renderer")->capture_default_str();
  addThreadsOption(cmd, args->threads);
  cmd->add_option("--width", args->width, "Image width override");
  cmd->add_option("--height", args->height, "Image height override");
  cmd->add_flag("!--no-accuracy", args->accuracy, "hw engines: skip the accuracy line (no reference render)");
  addReferenceCacheOptions(cmd, args->use_cache, args->cache_dir);
  addLimitOptions(cmd, args->limits);
  addViewCullOption(cmd, args->view_cull);
  cmd->callback([args] {
    checkImageSize(args->width, args->height);
    std::filesystem::create_directories(args->out);
    std::printf("%-16s %10s %11s %14s %12s\n", "scene", "primitives", "size", "pixels covered", "ms");
    double total = 0;
    std::size_t failed = 0;
    for (const auto& path : args->scenes) {
      RenderJob job;
      job.scene_path = path;
      job.engine = args->engine;
      job.width = args->width;
      job.height = args->height;
      job.options.threads = args->threads;
      job.options.report_accuracy = args->accuracy;
      job.options.limits = args->limits;
      job.use_cache = args->use_cache;
      job.cache_dir = args->cache_dir;
      job.view_cull = args->view_cull;
      job.color_path = (std::filesystem::path(args->out) / std::filesystem::path(path).stem()).string() + ".png";
      RenderJobResult r;
      try {
        r = runRenderJob(job);
      } catch (const std::exception& e) {
        std::fflush(stdout);
        std::fprintf(stderr, "qacc: error: %s\n", e.what());
        ++failed;
        continue;
      }
      const std::string size = std::to_string(r.scene.width) + "x" + std::to_string(r.scene.height);
      std::printf("%-16s %10zu %11s %14zu %12.1f\n", r.scene.name.c_str(), r.scene.primitives.size(), size.c_str(),
                  r.result.fb.covered(), r.result.host_ms);
      if (!r.result.accuracy.empty()) std::printf("  %s\n", r.result.accuracy.c_str());
      std::fflush(stdout);
      total += r.result.host_ms;
    }
    std::printf("%zu scenes rendered with engine %s into %s/ in %.1f ms\n", args->scenes.size() - failed,
                args->engine.c_str(), args->out.c_str(), total);
    if (failed > 0)
      throw std::runtime_error(std::to_string(failed) + " of " + std::to_string(args->scenes.size()) +
                               " scenes could not be rendered (see the errors above)");
  });
}

}  // namespace qacc
