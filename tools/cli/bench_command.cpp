// qacc bench [SCENE...] [--width W --height H] [--config FILE] [--threads N,...] [--repeat N]
//            [--no-cycle] [--zoomed-fov DEG] [--json FILE]
// Accelerator benchmark (issues 3 and 16): per scene (default: molecule and sphereflake at
// 1920x1080) and per thread count (default: 1 and all cores), the reference, `hw` and
// `hw-cycle` wall time per frame (best of --repeat, the engines alternating so that they
// see the same machine load; a frame ends when the engine returns, its result freed after
// the clock stops) with the page faults of that best frame, the `hw` tested pixels per
// second (per thread too), the `hw-cycle` simulated cycles, the wall time of its pixel
// datapath pass (pixel_trace.h), the simulation rate of the timing loop alone (simulated
// cycles per wall second, one core), the slowdown of the whole `hw-cycle` frame against the modeled clock, and the
// modeled frame time at the configured clock; the header gives the configuration's
// silicon cost (cost_model.h) and the load average. Then the ratios the performance
// targets are stated in (docs/PERFORMANCE.md): hw against the reference at each thread
// count, and each engine from the first thread count to the last. Each scene's build (read,
// parse, model, culled to the view: "build ms", once) is timed too; --zoomed-fov DEG benches
// every scene a second time with its perspective camera's fov_y_deg set to DEG, the build
// and the frames of the zoomed view beside the full one's (docs/SCENES.md "View culling").
// --json FILE writes all
// of it with the machine (CPU model, cores); --out OUT writes the runs as OUT.json and
// OUT.csv rows, as `reduce` and `sweep` do. Nothing is asserted.
#include <nlohmann/json.hpp>
#include <sys/resource.h>

#include <algorithm>
#include <chrono>
#include <cstdio>
#include <cstdlib>
#include <fstream>
#include <memory>
#include <stdexcept>
#include <string>
#include <thread>

#include "hw_model/engines/cycle_engine.h"
#include "hw_model/engines/functional_engine.h"
#include "hw_model/report/cost_model.h"
#include "hw_model/report/stats_file.h"
#include "modeling/loader/scene_loader.h"
#include "modeling/scene/scene_error.h"
#include "raster/reference/reference_renderer.h"
#include "tools/bench/load_average.h"
#include "tools/cli/commands.h"
#include "tools/report/build_info.h"
#include "tools/engines/image_size.h"
#include "tools/cli/limit_options.h"
#include "tools/cli/view_cull_option.h"

namespace qacc {

namespace {

struct BenchArgs {
  std::vector<std::string> scenes;
  int width = 1920, height = 1080;
  std::string config;
  std::vector<int> threads;
  int repeat = 3;
  bool cycle = true;
  double zoomed_fov = 0;  // > 0: each scene also with fov_y_deg = zoomed_fov
  Limits limits;
  bool view_cull = true;
  std::string out;   // OUT.json and OUT.csv, one row per scene and thread count
  std::string json;
};

struct BenchRun {
  std::string scene;
  std::string view = "full";  // or "zoomed"
  double buildMs = 0;         // the scene's read, parse and build
  std::size_t primitives = 0;
  int threads = 0;
  double refMs = 1e300, hwMs = 1e300, cycleMs = 1e300;
  std::uint64_t tested = 0, cycles = 0;
  double loopS = 0, traceS = 0, frameMs = 0;
  long refFaults = 0, hwFaults = 0, cycleFaults = 0;  // minor page faults of each engine's best frame
  std::string clock;  // how hw-cycle's simulator went through the main pass (HwStats::simulator_clock)
  double testedPerSecond() const { return double(tested) / (hwMs * 1e-3); }
  double loopRate() const { return loopS > 0 ? double(cycles) / loopS : 0.0; }
};

double wallMs(std::chrono::steady_clock::time_point t0) {
  return std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - t0).count();
}

std::string cpuModel() {
  std::ifstream in("/proc/cpuinfo");
  std::string line;
  while (std::getline(in, line))
    if (line.rfind("model name", 0) == 0) {
      const auto colon = line.find(':');
      if (colon != std::string::npos) return line.substr(line.find_first_not_of(" \t", colon + 1));
    }
  return "unknown";
}

// The scene text with its perspective camera's vertical field of view set to `fov` degrees.
std::string withFieldOfView(const std::string& text, const std::string& path, double fov) {
  nlohmann::json doc = nlohmann::json::parse(text, nullptr, false);
  // Text that is not a scene with a camera object goes to the loader as it is, for its error.
  if (doc.is_discarded() || !doc.is_object() || !doc.contains("camera") || !doc["camera"].is_object()) return text;
  const nlohmann::json& type = doc["camera"].contains("type") ? doc["camera"]["type"] : nlohmann::json("perspective");
  if (type != "perspective") throw SceneError(path, "/camera/type", "--zoomed-fov needs a perspective camera");
  doc["camera"]["fov_y_deg"] = fov;
  return doc.dump();
}

// One timed frame: the engine's wall time and the minor page faults of the whole process
// during it (frame-sized buffers first touched), the result kept alive until the clock has
// stopped, so that no engine's time includes freeing its own frame.
struct FrameTiming {
  double ms = 0;
  long faults = 0;
};
long minorFaults() {
  rusage u{};
  getrusage(RUSAGE_SELF, &u);
  return u.ru_minflt;
}
template <typename Render, typename Keep>
FrameTiming timeFrame(Render&& render, Keep&& keep) {
  const long f0 = minorFaults();
  const auto t0 = std::chrono::steady_clock::now();
  auto result = render();
  FrameTiming t{wallMs(t0), minorFaults() - f0};
  keep(result);
  return t;
}

BenchRun benchOne(const Scene& scene, const HwConfig& cfg, int threads, int repeat, bool cycle) {
  BenchRun b;
  b.scene = scene.name;
  b.primitives = scene.primitives.size();
  b.threads = threads;
  const auto best = [](const FrameTiming& t, double& ms, long& faults) {
    if (t.ms < ms) {
      ms = t.ms;
      faults = t.faults;
    }
  };
  for (int i = 0; i < repeat; ++i) {
    best(timeFrame([&] { return renderReference(scene, threads); }, [](const auto&) {}), b.refMs, b.refFaults);
    best(timeFrame([&] { return renderHw(scene, cfg, threads); },
                   [&](const HwRender& hw) { b.tested = hw.stats.pixels.tested; }),
         b.hwMs, b.hwFaults);
    if (!cycle) continue;
    double loopS = 0, traceS = 0;  // of this frame, kept if it is the best
    const FrameTiming t = timeFrame([&] { return renderHwCycle(scene, cfg, threads); },
                                    [&](const HwRender& r) {
                                      b.cycles = r.stats.cycles;
                                      b.frameMs = r.stats.frameSeconds() * 1e3;
                                      loopS = r.stats.loop_seconds;
                                      traceS = r.stats.trace_seconds;
                                      b.clock = r.stats.simulator_clock;
                                    });
    if (t.ms < b.cycleMs) {
      b.loopS = loopS;
      b.traceS = traceS;
    }
    best(t, b.cycleMs, b.cycleFaults);
  }
  if (!cycle) b.cycleMs = 0;
  return b;
}

nlohmann::json toJson(const BenchRun& b) {
  return {{"scene", b.scene},
          {"view", b.view},
          {"build_ms", b.buildMs},
          {"primitives", b.primitives},
          {"threads", b.threads},
          {"ref_ms", b.refMs},
          {"hw_ms", b.hwMs},
          {"hw_cycle_ms", b.cycleMs},
          {"ref_page_faults", b.refFaults},
          {"hw_page_faults", b.hwFaults},
          {"hw_cycle_page_faults", b.cycleFaults},
          {"cycles", b.cycles},
          {"loop_seconds", b.loopS},
          {"trace_seconds", b.traceS},
          {"loop_cycles_per_second", b.loopRate()},
          {"simulator_clock", b.clock},
          {"tested_pixels", b.tested},
          {"tested_pixels_per_second", b.testedPerSecond()},
          {"tested_pixels_per_second_per_thread", b.testedPerSecond() / b.threads},
          {"modeled_frame_ms", b.frameMs},
          {"hw_cycle_slowdown", b.frameMs > 0 ? b.cycleMs / b.frameMs : 0.0}};
}

void runBench(const BenchArgs& a) {
  checkImageSize(a.width, a.height);
  const HwConfig cfg = a.config.empty() ? HwConfig() : loadHwConfig(a.config);
  std::vector<std::string> scenes = a.scenes;
  if (scenes.empty())
    scenes = {qaccSourceDir() + "/scenes/molecule.json", qaccSourceDir() + "/scenes/sphereflake.json"};
  const int cores = int(std::max(1u, std::thread::hardware_concurrency()));
  std::vector<int> threads = a.threads;
  if (threads.empty()) threads = cores > 1 ? std::vector<int>{1, cores} : std::vector<int>{1};
  const double load0 = loadAverage();
  std::printf("config %s, %d MHz, P=%d, %.0f kGE (cost model), %dx%d, best of %d; %s, %d cores, load %.2f\n",
              cfg.name.c_str(), int(cfg.clock_mhz), cfg.pipelines, CostModel::of(cfg).totalGe() / 1e3, a.width,
              a.height, a.repeat, cpuModel().c_str(), cores, load0);
  std::printf("%-14s %-6s %9s %7s %3s %9s %9s %7s %12s %10s %11s %9s %11s %9s %9s  %s\n", "scene", "view",
              "build ms", "prims", "thr", "ref ms", "hw ms", "ref/hw", "tested px/s", "cycle ms", "cycles", "trace ms",
              "loop cyc/s", "slowdown", "frame ms", "faults ref/hw/cycle");
  std::vector<BenchRun> runs;
  std::vector<double> fovs = {0};  // 0: the scene's own camera
  if (a.zoomed_fov > 0) fovs.push_back(a.zoomed_fov);
  for (const std::string& path : scenes)
    for (double fov : fovs) {
      const auto t0 = std::chrono::steady_clock::now();
      std::string text = readSceneText(path, a.limits);
      if (fov > 0) text = withFieldOfView(text, path, fov);
      Scene scene = parseScene(text, path, sceneDirectory(path), a.limits, ViewCulling{a.view_cull, a.width, a.height});
      const double buildMs = wallMs(t0);
      applyImageSize(scene, a.width, a.height);
      for (int t : threads) {
        BenchRun b = benchOne(scene, cfg, t, a.repeat, a.cycle);
        b.view = fov > 0 ? "zoomed" : "full";
        b.buildMs = buildMs;
        std::printf("%-14s %-6s %9.1f %7zu %3d %9.1f %9.1f %7.2f %12.3g %10.1f %11llu %9.1f %11.3g %9.2f %9.3f"
                    "  %ld/%ld/%ld\n",
                    b.scene.c_str(), b.view.c_str(), b.buildMs, b.primitives, b.threads, b.refMs, b.hwMs,
                    b.refMs / b.hwMs, b.testedPerSecond(), b.cycleMs, (unsigned long long)b.cycles, b.traceS * 1e3,
                    b.loopRate(), b.frameMs > 0 ? b.cycleMs / b.frameMs : 0.0, b.frameMs, b.refFaults, b.hwFaults,
                    b.cycleFaults);
        std::fflush(stdout);
        runs.push_back(b);
      }
    }
  // Scaling from the first thread count to the last, per scene, view and engine.
  nlohmann::json scaling = nlohmann::json::array();
  if (threads.size() > 1)
    for (std::size_t i = 0; i < runs.size(); i += threads.size()) {
      const BenchRun& lo = runs[i];
      const BenchRun& hi = runs[i + threads.size() - 1];
      std::printf("%s (%s): %d -> %d threads: reference x%.2f, hw x%.2f%s\n", lo.scene.c_str(), lo.view.c_str(),
                  lo.threads, hi.threads,
                  lo.refMs / hi.refMs, lo.hwMs / hi.hwMs,
                  a.cycle ? (", hw-cycle x" + std::to_string(lo.cycleMs / hi.cycleMs).substr(0, 4)).c_str() : "");
      scaling.push_back({{"scene", lo.scene},
                         {"view", lo.view},
                         {"from_threads", lo.threads},
                         {"to_threads", hi.threads},
                         {"ref_speedup", lo.refMs / hi.refMs},
                         {"hw_speedup", lo.hwMs / hi.hwMs},
                         {"hw_cycle_speedup", a.cycle ? lo.cycleMs / hi.cycleMs : 0.0}});
    }
  const double load1 = loadAverage();
  if (a.cycle && !runs.empty())
    std::printf("hw-cycle's simulator clock: %s (loop cyc/s is its rate)\n", runs.front().clock.c_str());
  std::printf("load average %.2f at the start, %.2f at the end\n", load0, load1);
  if (!a.out.empty()) {
    nlohmann::ordered_json rows = nlohmann::ordered_json::array();
    for (const BenchRun& b : runs) {
      nlohmann::ordered_json row;
      row["config"] = cfg.name;
      row["width"] = a.width;
      row["height"] = a.height;
      row["gates_kge"] = CostModel::of(cfg).totalGe() / 1e3;
      const nlohmann::json fields = toJson(b);
      for (auto it = fields.begin(); it != fields.end(); ++it) row[it.key()] = *it;
      rows.push_back(row);
    }
    writeResultRows(a.out, "qacc-bench/1", rows);
  }
  if (a.json.empty()) return;
  nlohmann::json doc;
  doc["format"] = "qacc-bench/1";
  doc["machine"] = {{"cpu_model", cpuModel()}, {"cores", cores}, {"load_start", load0}, {"load_end", load1}};
  doc["config"] = cfg.name;
  doc["clock_mhz"] = cfg.clock_mhz;
  doc["width"] = a.width;
  doc["height"] = a.height;
  doc["repeat"] = a.repeat;
  if (a.zoomed_fov > 0) doc["zoomed_fov_deg"] = a.zoomed_fov;
  doc["runs"] = nlohmann::json::array();
  for (const BenchRun& b : runs) doc["runs"].push_back(toJson(b));
  doc["scaling"] = scaling;
  std::ofstream out(a.json);
  out << doc.dump(2) << "\n";
  if (!out) throw std::runtime_error(a.json + ": cannot write the benchmark JSON");
}

}  // namespace

void addBenchCommand(CLI::App& app) {
  auto args = std::make_shared<BenchArgs>();
  CLI::App* cmd = app.add_subcommand("bench", "Accelerator benchmark: hw vs reference time, hw-cycle simulation rate, modeled fps");
  cmd->add_option("scenes", args->scenes, "Scene files (default: molecule and sphereflake)");
  cmd->add_option("--width", args->width, "Image width")->capture_default_str();
  cmd->add_option("--height", args->height, "Image height")->capture_default_str();
  cmd->add_option("--config", args->config, "Accelerator configuration JSON");
  cmd->add_option("--threads", args->threads, "Thread counts, e.g. 1,2 (default: 1 and all cores)")
      ->delimiter(',')
      ->check(CLI::Range(1, 1024));
  cmd->add_option("--repeat", args->repeat, "Frames timed per engine (best is kept)")->capture_default_str()->check(CLI::Range(1, 100));
  cmd->add_flag("!--no-cycle", args->cycle, "Skip the hw-cycle run");
  cmd->add_option("--zoomed-fov", args->zoomed_fov,
                  "Also bench each scene zoomed: its perspective camera's fov_y_deg set to DEG")
      ->check(CLI::Range(1e-3, 179.0));
  cmd->add_option("--json", args->json, "Also write the results as JSON (with the machine)");
  cmd->add_option("--out", args->out, "Write the table as OUT.json and OUT.csv");
  addLimitOptions(cmd, args->limits);
  addViewCullOption(cmd, args->view_cull);
  cmd->callback([args] { runBench(*args); });
}

}  // namespace qacc
