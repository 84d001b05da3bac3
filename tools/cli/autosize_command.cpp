// qacc autosize SCENE... --target "wrong<=0.1%,pinholes=0" [--config BASE] [--keys K,K]
//               [--step BITS] [--values KEY=V:V:V]... [--width W --height H] [--cache DIR]
//               [--threads N] [--verbose] [-o best.json]
// The cheapest configuration (cost model) whose renders of every scene meet the target,
// by the search of tools/sweep/autosize.h; prints it and writes it as a configuration file.
#include <cstdio>
#include <fstream>
#include <memory>
#include <sstream>

#include "tools/cli/commands.h"
#include "tools/cli/threads_option.h"
#include "tools/engines/reference_cache.h"
#include "tools/sweep/autosize.h"
#include "tools/sweep/sweep_results.h"

namespace qacc {

namespace {

struct AutosizeArgs {
  std::vector<std::string> scenes;
  std::string target;
  std::string config;
  std::string keys;
  int step = 2;
  std::vector<std::string> values;
  int width = 0, height = 0;
  std::string cache;
  int threads = 0;
  bool verbose = false;
  std::string output;
};

std::vector<std::string> split(const std::string& s, char sep) {
  std::vector<std::string> out;
  std::stringstream ss(s);
  std::string item;
  while (std::getline(ss, item, sep))
    if (!item.empty()) out.push_back(item);
  return out;
}

void runAutosize(const AutosizeArgs& a) {
  AutosizeOptions o;
  o.scenes = a.scenes;
  o.target = parseAccuracyTarget(a.target);
  o.base = a.config.empty() ? HwConfig() : loadHwConfig(a.config);
  o.keys = split(a.keys, ',');
  o.step = a.step;
  o.verbose = a.verbose;
  for (const std::string& kv : a.values) {
    const auto eq = kv.find('=');
    if (eq == std::string::npos) throw std::invalid_argument("--values: '" + kv + "' is not KEY=V:V:V");
    std::vector<int> vs;
    for (const std::string& t : split(kv.substr(eq + 1), ':')) {
      std::size_t pos = 0;
      int v = 0;
      try {
        v = std::stoi(t, &pos);
      } catch (...) {
        pos = 0;
      }
      if (pos != t.size() || t.empty()) throw std::invalid_argument("--values: '" + t + "' in '" + kv + "' is not an integer");
      vs.push_back(v);
    }
    if (vs.empty()) throw std::invalid_argument("--values: no value in '" + kv + "'");
    o.values[kv.substr(0, eq)] = vs;
  }
  if ((a.width > 0) != (a.height > 0)) throw std::invalid_argument("--width and --height go together");
  if (a.width > 0) o.knobs["scene.size"] = {a.width, a.height};
  ReferenceCache cache(a.cache);
  SweepEvaluator ev("hw", a.threads, cache);
  const AutosizeResult r = autosize(o, ev);
  std::printf("autosize: target %s on %zu scene(s); bounds of each width alone:", a.target.c_str(), a.scenes.size());
  for (const auto& [k, v] : r.bound) std::printf(" %s>=%d", k.c_str(), v);
  std::printf("\nautosize: %zu candidate configurations, %zu rendered (each on every scene until one fails)\n", r.grid,
              r.evaluations);
  if (!r.found) throw std::invalid_argument("autosize: no candidate configuration meets " + a.target);
  std::printf("autosize: cheapest configuration meeting the target: %.1f kGE (base %s: %.1f kGE), worst scene %.4f%% wrong, "
              "%s\n",
              r.gates_kge, o.base.name.c_str(), r.base_gates_kge, r.worst_wrong_percent,
              lowestPsnrText(r.worst_psnr_db).c_str());
  for (const auto& k : hwConfigKeys())
    if (isHwWidthKey(k)) {
      const int v = hwConfigValue(r.best, k).get<int>(), b = hwConfigValue(o.base, k).get<int>();
      std::printf("  %-16s %3d%s\n", k.c_str(), v, v != b ? ("  (base " + std::to_string(b) + ")").c_str() : "");
    }
  if (!a.output.empty()) {
    std::ofstream out(a.output);
    out << hwConfigToJson(r.best) << "\n";
    if (!out) throw std::invalid_argument(a.output + ": cannot write");
    std::printf("autosize: written to %s\n", a.output.c_str());
  }
}

}  // namespace

void addAutosizeCommand(CLI::App& app) {
  auto args = std::make_shared<AutosizeArgs>();
  CLI::App* cmd = app.add_subcommand("autosize", "Cheapest configuration (cost model) meeting an accuracy target on the scenes");
  cmd->add_option("scenes", args->scenes, "Scene files")->required();
  cmd->add_option("--target", args->target, "Accuracy target, e.g. \"wrong<=0.1%,pinholes=0\"")->required();
  cmd->add_option("--config", args->config, "Base configuration (default: the default configuration)");
  cmd->add_option("--keys", args->keys, "Comma-separated width keys to search (default: every width key)");
  cmd->add_option("--step", args->step, "Bits between candidate widths")->capture_default_str()->check(CLI::Range(1, 16));
  cmd->add_option("--values", args->values, "Explicit candidates of a key: KEY=V:V:V (repeatable)");
  cmd->add_option("--width", args->width, "Image width (with --height)")->check(CLI::Range(8, 8192));
  cmd->add_option("--height", args->height, "Image height (with --width)")->check(CLI::Range(8, 8192));
  cmd->add_option("--cache", args->cache, "Reference cache directory (default $QACC_CACHE or ~/.cache/qacc)");
  addThreadsOption(cmd, args->threads);
  cmd->add_flag("--verbose", args->verbose, "Print every configuration rendered in the cost-ordered walk");
  cmd->add_option("-o,--output", args->output, "Write the configuration found (JSON)");
  cmd->callback([args] { runAutosize(*args); });
}

}  // namespace qacc
