// qacc bench-load [--counts N,...] [--repeat R] [--dir DIR]
// Loading benchmark: per count N (default 100 000, 200 000, 500 000 and 1 000 000), the
// scene of N spheres in view (tools/bench/sphere_grid_scene.h) is written to a file and
// loaded as every command loads a scene (loadScene: read, parse, build, view culling), best
// of --repeat. Printed per N: the file's size, the wall and CPU (process) time of the load,
// the CPU time per object, and that per-object time as a ratio to the first count's: loading
// is linear in the objects when the ratio stays near 1 (a quadratic loader doubles it with
// every doubling of N). CPU time is the figure to quote on a shared machine: wall time also
// counts the time other processes held the cores. --dir keeps the scene files there (to
// render them); without it they go to a temporary directory that is removed. Nothing is
// asserted.
#include <unistd.h>

#include <algorithm>
#include <chrono>
#include <cstdio>
#include <cstdlib>
#include <ctime>
#include <filesystem>
#include <fstream>
#include <memory>
#include <stdexcept>
#include <string>
#include <vector>

#include "modeling/loader/scene_loader.h"
#include "tools/bench/load_average.h"
#include "tools/bench/sphere_grid_scene.h"
#include "tools/cli/commands.h"

namespace qacc {

namespace {

namespace fs = std::filesystem;

struct BenchLoadArgs {
  std::vector<long long> counts{100000, 200000, 500000, 1000000};
  int repeat = 1;
  std::string dir;
};

double processCpuSeconds() {
  timespec t{};
  clock_gettime(CLOCK_PROCESS_CPUTIME_ID, &t);
  return double(t.tv_sec) + 1e-9 * double(t.tv_nsec);
}

void runBenchLoad(const BenchLoadArgs& a) {
  const bool keep = !a.dir.empty();
  const fs::path dir = keep ? fs::path(a.dir) : fs::temp_directory_path() / ("qacc-bench-load-" + std::to_string(getpid()));
  fs::create_directories(dir);
  const double load0 = loadAverage();
  std::printf("loading N spheres in view (320x240, perspective), best of %d; load average %.2f\n", a.repeat, load0);
  std::printf("%9s %9s %9s %9s %13s %9s\n", "objects", "MB", "wall s", "CPU s", "CPU us/object", "ratio");
  double firstPerObject = 0;
  for (const long long n : a.counts) {
    const fs::path file = dir / ("spheres_" + std::to_string(n) + ".json");
    const std::string text = sphereGridScene(std::size_t(n));
    {
      std::ofstream out(file, std::ios::binary);
      out << text;
      if (!out) throw std::runtime_error(file.string() + ": cannot write the scene");
    }
    double wall = 1e300, cpu = 1e300;
    for (int r = 0; r < a.repeat; ++r) {
      const auto w0 = std::chrono::steady_clock::now();
      const double c0 = processCpuSeconds();
      const Scene scene = loadScene(file.string());
      const double c1 = processCpuSeconds();
      const auto w1 = std::chrono::steady_clock::now();
      if (scene.primitives.size() != std::size_t(n))
        throw std::runtime_error(file.string() + ": loaded " + std::to_string(scene.primitives.size()) +
                                 " primitives, expected " + std::to_string(n));
      wall = std::min(wall, std::chrono::duration<double>(w1 - w0).count());
      cpu = std::min(cpu, c1 - c0);
    }
    const double perObject = cpu / double(n);
    if (firstPerObject == 0) firstPerObject = perObject;
    std::printf("%9lld %9.1f %9.3f %9.3f %13.3f %9.2f\n", n, double(text.size()) / 1e6, wall, cpu, perObject * 1e6,
                perObject / firstPerObject);
    std::fflush(stdout);
    if (!keep) fs::remove(file);
  }
  if (!keep) fs::remove(dir);
  std::printf("load average %.2f at the start, %.2f at the end%s\n", load0, loadAverage(),
              keep ? (", scenes kept in " + dir.string()).c_str() : "");
}

}  // namespace

void addBenchLoadCommand(CLI::App& app) {
  auto args = std::make_shared<BenchLoadArgs>();
  CLI::App* cmd = app.add_subcommand("bench-load", "Loading benchmark: load time of N spheres for several N, per object");
  cmd->add_option("--counts", args->counts, "Sphere counts, e.g. 100000,1000000 (default 1e5, 2e5, 5e5, 1e6)")
      ->delimiter(',')
      ->check(CLI::Range(1LL, 10000000LL));
  cmd->add_option("--repeat", args->repeat, "Loads timed per count (best is kept)")->capture_default_str()->check(CLI::Range(1, 100));
  cmd->add_option("--dir", args->dir, "Write the scene files into DIR and keep them (default: a temporary directory)");
  cmd->callback([args] { runBenchLoad(*args); });
}

}  // namespace qacc
