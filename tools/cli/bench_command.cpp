// qacc bench [SCENE...] [--width W --height H] [--config FILE] [--threads N] [--repeat N]
// Accelerator benchmark (issue 3): per scene (default: molecule and sphereflake at
// 1920x1080) the reference and `hw` wall time per frame (best of --repeat), the
// `hw-cycle` simulated cycles, its host CPU seconds (setup, pixel datapath pass, timing
// loop, final shading), the wall time of the pixel datapath pass (pixel_trace.h), the
// simulation rate of the timing loop alone (simulated cycles per wall second, one core),
// the slowdown (host seconds / modeled seconds), and the modeled frame time and fps at the
// configured clock; the header gives the configuration's silicon cost (cost_model.h).
// Prints a table; nothing is asserted.
#include <chrono>
#include <cstdio>
#include <ctime>
#include <memory>

#include "hw_model/report/cost_model.h"
#include "hw_model/engines/cycle_engine.h"
#include "hw_model/engines/functional_engine.h"
#include "modeling/loader/scene_loader.h"
#include "raster/reference/reference_renderer.h"
#include "tools/cli/commands.h"
#include "tools/cli/limit_options.h"

namespace qacc {

namespace {

struct BenchArgs {
  std::vector<std::string> scenes;
  int width = 1920, height = 1080;
  std::string config;
  int threads = 0;
  int repeat = 3;
  bool cycle = true;
  Limits limits;
};

double wallMs(std::chrono::steady_clock::time_point t0) {
  return std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - t0).count();
}

void runBench(const BenchArgs& a) {
  const HwConfig cfg = a.config.empty() ? HwConfig() : loadHwConfig(a.config);
  std::vector<std::string> scenes = a.scenes;
  if (scenes.empty())
    scenes = {std::string(QACC_SOURCE_DIR) + "/scenes/molecule.json", std::string(QACC_SOURCE_DIR) + "/scenes/sphereflake.json"};
  std::printf("config %s, %d MHz, P=%d, %.0f kGE (cost model), %dx%d, threads %d, best of %d\n", cfg.name.c_str(),
              int(cfg.clock_mhz), cfg.pipelines, CostModel::of(cfg).totalGe() / 1e3, a.width, a.height, a.threads,
              a.repeat);
  std::printf("%-14s %8s %10s %10s %7s %12s %9s %9s %12s %9s %10s %8s\n", "scene", "prims", "ref ms", "hw ms",
              "hw/ref", "cycles", "host s", "trace s", "loop cyc/s", "slowdown", "frame ms", "fps");
  for (const std::string& path : scenes) {
    Scene scene = loadScene(path, a.limits);
    scene.width = a.width;
    scene.height = a.height;
    double refMs = 1e300, hwMs = 1e300;
    for (int i = 0; i < a.repeat; ++i) {
      auto t0 = std::chrono::steady_clock::now();
      renderReference(scene, a.threads);
      refMs = std::min(refMs, wallMs(t0));
      t0 = std::chrono::steady_clock::now();
      renderHw(scene, cfg, a.threads);
      hwMs = std::min(hwMs, wallMs(t0));
    }
    std::uint64_t cycles = 0;
    double hostS = 0, frameMs = 0, loopS = 0, traceS = 0;
    if (a.cycle) {
      const std::clock_t c0 = std::clock();
      const HwRender r = renderHwCycle(scene, cfg, a.threads);
      // CPU seconds of the process; the cycle loop itself is single-threaded.
      hostS = double(std::clock() - c0) / CLOCKS_PER_SEC;
      cycles = r.stats.cycles;
      frameMs = r.stats.frameSeconds() * 1e3;
      loopS = r.stats.loop_seconds;
      traceS = r.stats.trace_seconds;
    }
    std::printf("%-14s %8zu %10.1f %10.1f %7.2f %12llu %9.2f %9.3f %12.3g %9.0f %10.3f %8.1f\n", scene.name.c_str(),
                scene.primitives.size(), refMs, hwMs, hwMs / refMs, (unsigned long long)cycles, hostS, traceS,
                loopS > 0 ? double(cycles) / loopS : 0.0, frameMs > 0 ? hostS * 1e3 / frameMs : 0.0, frameMs,
                frameMs > 0 ? 1e3 / frameMs : 0.0);
    std::fflush(stdout);
  }
}

}  // namespace

void addBenchCommand(CLI::App& app) {
  auto args = std::make_shared<BenchArgs>();
  CLI::App* cmd = app.add_subcommand("bench", "Accelerator benchmark: hw vs reference time, hw-cycle simulation rate, modeled fps");
  cmd->add_option("scenes", args->scenes, "Scene files (default: molecule and sphereflake)");
  cmd->add_option("--width", args->width, "Image width")->capture_default_str()->check(CLI::Range(1, 16384));
  cmd->add_option("--height", args->height, "Image height")->capture_default_str()->check(CLI::Range(1, 16384));
  cmd->add_option("--config", args->config, "Accelerator configuration JSON");
  cmd->add_option("--threads", args->threads, "Threads (default: all cores)")->check(CLI::Range(1, 1024));
  cmd->add_option("--repeat", args->repeat, "Frames timed per engine (best is kept)")->capture_default_str()->check(CLI::Range(1, 100));
  cmd->add_flag("!--no-cycle", args->cycle, "Skip the hw-cycle run");
  addLimitOptions(cmd, args->limits);
  cmd->callback([args] { runBench(*args); });
}

}  // namespace qacc
