// qacc sweep SPEC.json --out DIR [--shard I/N] [--cache DIR] [--threads N] [--no-report]
// qacc sweep --merge DIR... --out DIR [--no-report]
//
// The speed/accuracy trade, measured (docs/SWEEP.md): every point of the spec
// (tools/sweep/sweep_spec.h) on every scene, measured by tools/sweep/sweep_evaluator.h,
// written as DIR/results.{json,csv} and DIR/fronts.csv (tools/sweep/sweep_results.h); then
// tools/plot_sweep.py draws the plots (PNG and SVG) and DIR/report.html. A shard runs the
// items with item % N == I - 1; --merge joins the shards' directories into one.
#include <cstdio>
#include <cstdlib>
#include <filesystem>
#include <memory>
#include <string>
#include <vector>

#include "tools/cli/commands.h"
#include "tools/cli/threads_option.h"
#include "hw_model/report/stats_file.h"
#include "tools/report/build_info.h"
#include "tools/engines/reference_cache.h"
#include "tools/sweep/sweep_results.h"
#include "tools/sweep/sweep_runner.h"

namespace qacc {

namespace fs = std::filesystem;

namespace {

struct SweepArgs {
  std::string spec;
  std::string out;
  std::string shard;
  std::vector<std::string> merge;
  std::string cache;
  int threads = 0;
  bool report = true;
  bool noCache = false;
};

std::string shellQuote(const std::string& s) {
  std::string q = "'";
  for (char c : s) q += c == '\'' ? std::string("'\\''") : std::string(1, c);
  return q + "'";
}

void makeReport(const std::string& out) {
  const std::string script = qaccToolsDir() + "/plot_sweep.py";
  // Debian's interpreter, where python3-matplotlib is, before any other python3 on PATH.
  const std::string python = fs::exists("/usr/bin/python3") ? "/usr/bin/python3" : "python3";
  const std::string cmd = python + " " + shellQuote(script) + " " + shellQuote(out);
  if (std::system(cmd.c_str()) != 0)
    std::fprintf(stderr, "qacc: warning: the plots and report.html were not made (%s failed; needs python3-matplotlib)\n",
                 cmd.c_str());
}

void printSummary(const SweepResults& r, const std::string& out) {
  std::size_t ok = 0, refused = 0, rendered = 0;
  double host = 0;
  for (const auto& row : r.rows) {
    if (row.value("status", std::string()) == "ok") ++ok;
    else ++refused;
    if (row.value("reference_rendered", false)) ++rendered;
    if (row.contains("host_seconds")) host += row["host_seconds"].get<double>();
  }
  std::printf("sweep %s: %zu items (%zu points x %zu scenes%s): %zu measured, %zu refused configurations; "
              "%zu reference renders; %.2f s in the accelerator engine; results in %s/\n",
              r.spec.value("name", std::string("?")).c_str(), r.rows.size(), r.points, r.scenes,
              r.shard.empty() ? "" : (", shard " + r.shard).c_str(), ok, refused, rendered, host, out.c_str());
  const nlohmann::ordered_json f = sweepFronts(r);
  if (f.contains("answer")) {
    const auto& a = f["answer"];
    if (a["point"].is_null())
      std::printf("target %s: %s\n", r.target.c_str(), a["note"].get<std::string>().c_str());
    else {
      // The colour error beside the target's classes.
      std::printf("target %s: cheapest point %zu (%s), %.1f kGE, worst scene %.4f%% wrong, %s\n", r.target.c_str(),
                  a["point"].get<std::size_t>(), a["label"].get<std::string>().c_str(), a["gates_kge"].get<double>(),
                  a["worst_wrong_percent"].get<double>(), lowestPsnrText(jsonNumberValue(a["worst_psnr_db"])).c_str());
    }
  }
}

void runSweepCommand(const SweepArgs& a) {
  if (!a.merge.empty()) {
    if (!a.spec.empty()) throw std::invalid_argument("--merge takes result directories, not a spec");
    if (!a.shard.empty()) throw std::invalid_argument("--merge and --shard do not go together");
    if (!a.cache.empty()) throw std::invalid_argument("--merge renders nothing: --cache is not used");
    std::vector<SweepResults> parts;
    for (const auto& d : a.merge) parts.push_back(readSweepResults(d));
    const SweepResults m = mergeSweepResults(parts, a.merge);
    writeSweepResults(a.out, m);
    // Thumbnails of the shards.
    for (const auto& d : a.merge) {
      const fs::path r = fs::path(d) / "renders";
      if (!fs::is_directory(r) || fs::equivalent(fs::path(d), fs::path(a.out))) continue;
      fs::create_directories(fs::path(a.out) / "renders");
      for (const auto& e : fs::directory_iterator(r))
        fs::copy_file(e.path(), fs::path(a.out) / "renders" / e.path().filename(), fs::copy_options::overwrite_existing);
    }
    printSummary(m, a.out);
    if (a.report) makeReport(a.out);
    return;
  }
  if (a.spec.empty()) throw std::invalid_argument("sweep: give a SPEC.json (or --merge DIR...)");
  const SweepSpec spec = loadSweepSpec(a.spec);
  const Shard shard = a.shard.empty() ? Shard{} : parseShard(a.shard);
  ReferenceCache cache(a.cache);
  if (a.noCache) cache.disable();
  SweepEvaluator ev(spec.engine, a.threads, cache);
  ev.setThumbnails(a.out, spec.thumbnail_width);
  fs::create_directories(a.out);
  const SweepResults r = runSweep(spec, shard, ev);
  writeSweepResults(a.out, r);
  printSummary(r, a.out);
  std::printf("reference cache %s: %zu hits, %zu renders\n", cache.directory().c_str(), cache.hits(), cache.renders());
  if (a.report && shard.count == 1) makeReport(a.out);
}

}  // namespace

void addSweepCommand(CLI::App& app) {
  auto args = std::make_shared<SweepArgs>();
  CLI::App* cmd = app.add_subcommand("sweep", "Measure the speed/accuracy trade over a spec's points (docs/SWEEP.md)");
  cmd->add_option("spec", args->spec, "Sweep specification (qacc-sweep/1 JSON)");
  cmd->add_option("--out", args->out, "Output directory")->required();
  cmd->add_option("--shard", args->shard, "Run shard I of N: the items with item % N == I - 1");
  cmd->add_option("--merge", args->merge, "Merge the result directories of the shards into --out")->expected(1, -1);
  cmd->add_option("--cache", args->cache, "Reference cache directory (default $QACC_CACHE or ~/.cache/qacc)");
  addThreadsOption(cmd, args->threads);
  cmd->add_flag("--no-cache", args->noCache, "Render the reference for every item (no reference cache)");
  cmd->add_flag("!--no-report", args->report, "Do not run tools/plot_sweep.py (plots, report.html)");
  cmd->callback([args] { runSweepCommand(*args); });
}

}  // namespace qacc
