// qacc sweep and qacc autosize: spec errors, grid and one-axis points, shard/merge
// equivalence through GNU parallel, the reference cache, autosize against an exhaustive
// sweep; and the command line's refusals of flags an engine does not read.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <cstdio>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <iterator>
#include <sstream>
#include <string>
#include <tuple>
#include <vector>

#include <nlohmann/json.hpp>

#include "tests/tools/command_run.h"
#include "tools/engines/reference_cache.h"
#include "hw_model/report/stats_file.h"
#include "tools/sweep/autosize.h"
#include "tools/sweep/pareto_front.h"
#include "tools/sweep/sweep_points.h"
#include "tools/sweep/sweep_results.h"
#include "tools/sweep/sweep_runner.h"

using namespace qacc;
namespace fs = std::filesystem;

namespace {

const std::string kSrc = QACC_SOURCE_DIR;

fs::path tempDir(const std::string& name) {
  const fs::path d = fs::path(QACC_BINARY_DIR) / "test_sweep" / name;
  fs::remove_all(d);
  fs::create_directories(d);
  return d;
}

std::string write(const fs::path& p, const std::string& text) {
  std::ofstream(p) << text;
  return p.string();
}

// A command's exit status and its output, standard error included.
qacc::CommandRun run(const std::string& cmd) { return qacc::runCommand(cmd + " 2>&1"); }

std::string qaccExe() { return QACC_EXE; }

// A small sweep: 2 scenes, 3 points (one axis), 96x72.
std::string tinySpec(const fs::path& dir) {
  return write(dir / "tiny.json", R"({"format": "qacc-sweep/1", "name": "tiny", "engine": "hw-cycle",
    "scenes": [")" + kSrc + R"(/scenes/gallery.json", ")" + kSrc + R"(/scenes/cylinders.json"],
    "size": [96, 72], "mode": "one_axis", "target": "wrong<=0.5%",
    "axes": [{"key": "value_bits", "values": [32, 20, 14]}, {"key": "delta_bits", "values": [48]}]})");
}

nlohmann::json results(const fs::path& dir) {
  std::ifstream in(dir / "results.json");
  return nlohmann::json::parse(in);
}

// Rows without the columns that depend on the host.
nlohmann::json comparable(const nlohmann::json& rows) {
  nlohmann::json out = nlohmann::json::array();
  for (auto row : rows) {
    for (auto it = row.begin(); it != row.end();) {
      if (isHostColumn(it.key())) it = row.erase(it);
      else ++it;
    }
    out.push_back(row);
  }
  return out;
}

}  // namespace

TEST(SweepSpec, PointsOfAGridAndOfOneAxis) {
  const fs::path d = tempDir("points");
  const std::string scene = kSrc + "/scenes/gallery.json";
  const std::string axes = R"("axes": [{"key": "value_bits", "values": [32, 24]}, {"key": "clip_bits", "range": [32, 16, -8]}])";
  SweepSpec g = loadSweepSpec(write(d / "g.json", R"({"format": "qacc-sweep/1", "scenes": [")" + scene + R"("], )" + axes + "}"));
  std::vector<SweepPoint> p = sweepPoints(g);
  ASSERT_EQ(p.size(), 6u);  // 2 x 3, first axis slowest
  EXPECT_EQ(p[0].label, "value_bits=32 clip_bits=32");
  EXPECT_EQ(p[1].label, "value_bits=32 clip_bits=24");
  EXPECT_EQ(p[3].label, "value_bits=24 clip_bits=32");
  EXPECT_EQ(p[5].config.value_bits, 24);
  EXPECT_EQ(p[5].config.clip_bits, 16);
  SweepSpec o = loadSweepSpec(
      write(d / "o.json", R"({"format": "qacc-sweep/1", "mode": "one_axis", "scenes": [")" + scene + R"("], )" + axes + "}"));
  p = sweepPoints(o);
  ASSERT_EQ(p.size(), 4u);  // base, value_bits=24, clip_bits=24, clip_bits=16 (32 is the base)
  EXPECT_EQ(p[0].label, "base");
  EXPECT_EQ(p[1].label, "value_bits=24");
  EXPECT_EQ(p[1].config.clip_bits, 32);
  EXPECT_EQ(p[3].label, "clip_bits=16");
  // Shards: every item in exactly one.
  for (std::size_t i = 0; i < 20; ++i) {
    int n = 0;
    for (int s = 1; s <= 3; ++s) n += Shard{s, 3}.takes(i);
    EXPECT_EQ(n, 1);
  }
  EXPECT_THROW(parseShard("0/3"), std::invalid_argument);
  EXPECT_THROW(parseShard("4/3"), std::invalid_argument);
  EXPECT_THROW(parseShard("1-3"), std::invalid_argument);
}

TEST(SweepSpec, ErrorsNameTheJsonPath) {
  const fs::path d = tempDir("errors");
  const std::string head = R"({"format": "qacc-sweep/1", "scenes": [")" + kSrc + R"(/scenes/gallery.json"], )";
  auto message = [&](const std::string& body) {
    try {
      loadSweepSpec(write(d / "bad.json", head + body + "}"));
    } catch (const std::exception& e) {
      return std::string(e.what());
    }
    return std::string("no error");
  };
  EXPECT_NE(message(R"("axes": [{"key": "value_bits", "values": [32, 99]}])").find("/axes/0/values/1"), std::string::npos);
  EXPECT_NE(message(R"("axes": [{"key": "valu_bits", "values": [32]}])").find("unknown accelerator configuration key"),
            std::string::npos);
  EXPECT_NE(message(R"("axes": [{"key": "scene.size", "values": [[96]]}])").find("/axes/0/values/0"), std::string::npos);
  EXPECT_NE(message(R"("axes": [], "engine": "facets")").find("/engine"), std::string::npos);
  EXPECT_NE(message(R"("axes": [], "colour": 1)").find("/colour"), std::string::npos);
  EXPECT_NE(message(R"("axes": [{"key": "clip_bits", "range": [8, 16, -2]}])").find("/axes/0/range"), std::string::npos);
}

TEST(ParetoFront, KeepsTheUndominated) {
  const std::vector<std::pair<double, double>> p = {{1, 5}, {2, 3}, {2, 4}, {3, 3}, {4, 1}, {5, 2}};
  EXPECT_EQ(paretoFront(p), (std::vector<std::size_t>{0, 1, 4}));
}

TEST(Sweep, ShardsThroughGnuParallelMergeToTheUnshardedRun) {
  ASSERT_EQ(run("parallel --version").status, 0) << "GNU parallel is missing (Debian package parallel, tools/deps.sh)";
  const fs::path d = tempDir("shards");
  const std::string spec = tinySpec(d);
  const std::string cache = "--cache " + (d / "cache").string();
  qacc::CommandRun whole = run(qaccExe() + " sweep " + spec + " --out " + (d / "whole").string() + " --no-report " + cache);
  ASSERT_EQ(whole.status, 0) << whole.out;
  qacc::CommandRun shards = run("parallel " + qaccExe() + " sweep " + spec + " --shard {}/3 --out " + (d / "part{}").string() +
                   " --no-report " + cache + " ::: 1 2 3");
  ASSERT_EQ(shards.status, 0) << shards.out;
  qacc::CommandRun merge = run(qaccExe() + " sweep --merge " + (d / "part1").string() + " " + (d / "part2").string() + " " +
                  (d / "part3").string() + " --out " + (d / "merged").string() + " --no-report");
  ASSERT_EQ(merge.status, 0) << merge.out;
  const nlohmann::json a = results(d / "whole"), b = results(d / "merged");
  EXPECT_EQ(a["rows"].size(), 8u);  // 4 points (one refused) x 2 scenes
  EXPECT_EQ(comparable(a["rows"]), comparable(b["rows"]));
  EXPECT_EQ(a["fronts"], b["fronts"]);
  // The answer gives its point's lowest PSNR beside the target's wrong pixels, as printed.
  const nlohmann::json& ans = a["fronts"]["answer"];
  ASSERT_TRUE(ans["point"].is_number()) << ans.dump();
  double lowest = INFINITY;
  for (const auto& row : a["rows"])
    if (row["point"] == ans["point"]) {
      ASSERT_TRUE(row["psnr_db"].is_number() || row["psnr_db"] == "inf") << row.dump();
      if (row["psnr_db"].is_number()) lowest = std::min(lowest, row["psnr_db"].get<double>());
    }
  if (std::isinf(lowest)) EXPECT_EQ(ans["worst_psnr_db"], "inf");
  else EXPECT_DOUBLE_EQ(ans["worst_psnr_db"].get<double>(), lowest);
  EXPECT_NE(whole.out.find("PSNR"), std::string::npos) << whole.out;
  // A missing shard is refused.
  qacc::CommandRun partial = run(qaccExe() + " sweep --merge " + (d / "part1").string() + " " + (d / "part2").string() + " --out " +
                    (d / "bad").string() + " --no-report");
  EXPECT_EQ(partial.status, 1);
  EXPECT_NE(partial.out.find("missing"), std::string::npos) << partial.out;
}

TEST(Sweep, SecondSweepRendersNoReference) {
  const fs::path d = tempDir("cache");
  const std::string spec = tinySpec(d);
  const std::string cmd = qaccExe() + " sweep " + spec + " --no-report --cache " + (d / "cache").string() + " --out ";
  qacc::CommandRun first = run(cmd + (d / "one").string());
  ASSERT_EQ(first.status, 0) << first.out;
  EXPECT_NE(first.out.find("2 renders"), std::string::npos) << first.out;  // one per scene
  qacc::CommandRun second = run(cmd + (d / "two").string());
  ASSERT_EQ(second.status, 0) << second.out;
  EXPECT_NE(second.out.find("0 renders"), std::string::npos) << second.out;
  const nlohmann::json two = results(d / "two"), one = results(d / "one");
  for (const auto& row : two["rows"])
    if (row["status"] == "ok") {
      EXPECT_FALSE(row["reference_rendered"].get<bool>());
    }
  EXPECT_EQ(comparable(one["rows"]), comparable(two["rows"]));
  // A refused configuration is a row with its reason.
  bool refused = false;
  for (const auto& row : one["rows"])
    if (row["status"] == "refused") refused = row["note"].get<std::string>().find("delta_bits") != std::string::npos;
  EXPECT_TRUE(refused);
  // The key changes with the scene's content and size.
  EXPECT_NE(ReferenceCache::key("{}", ".", 96, 72), ReferenceCache::key("{ }", ".", 96, 72));
  EXPECT_NE(ReferenceCache::key("{}", ".", 96, 72), ReferenceCache::key("{}", ".", 96, 73));
}

TEST(Sweep, TheSameImageReusesItsAccuracyFiguresAndThumbnails) {
  // An evaluator keeps, per reference, the last image it measured: a point whose image is the
  // same bit for bit (here: 1 and 4 pipelines after the default 2, a timing knob) takes its
  // figures and thumbnails from it; one with another image (value_bits 14, then the base again
  // after it) is measured. The timing knobs also take hw-cycle's setups, pixel trace and frame
  // from the point before (datapath_reused, hw_model/engines/datapath_reuse.h) and the scene
  // as loaded; the datapath change and the point after it compute theirs, and so does the
  // point at another size (a scene knob), but not the one after it (a timing knob). Every
  // row, reused or not, must equal the row of an evaluator that measured that point alone,
  // and every thumbnail must hold the same bytes.
  const fs::path d = tempDir("reuse");
  const std::string scene = kSrc + "/scenes/gallery.json";
  ReferenceCache cache((d / "cache").string());
  SweepEvaluator ev("hw-cycle", 1, cache);
  ev.setThumbnails((d / "run").string(), 48);
  const nlohmann::ordered_json small = {{"scene.size", {96, 72}}}, larger = {{"scene.size", {112, 84}}};
  std::vector<HwConfig> configs(7);
  configs[1].pipelines = 1;
  configs[2].pipelines = 4;
  configs[3].value_bits = 14;
  configs[6].zbuffer_banks = 8;
  const std::vector<bool> expectReused = {false, true, true, false, false, false, true};
  const std::string all = "setup, pixel trace, frame";
  const std::vector<std::string> expectDatapath = {"", all, all, "", "", "", all};
  const auto readFile = [](const fs::path& p) {
    std::ifstream in(p, std::ios::binary);
    return std::string(std::istreambuf_iterator<char>(in), {});
  };
  for (std::size_t i = 0; i < configs.size(); ++i) {
    const std::string name = "item" + std::to_string(i);
    const nlohmann::ordered_json& knobs = i < 5 ? small : larger;
    const nlohmann::ordered_json row = ev.evaluate(configs[i], knobs, scene, name);
    EXPECT_EQ(row["accuracy_reused"].get<bool>(), expectReused[i]) << name;
    EXPECT_EQ(row["datapath_reused"].get<std::string>(), expectDatapath[i]) << name;
    SweepEvaluator alone("hw-cycle", 1, cache);
    alone.setThumbnails((d / ("alone" + std::to_string(i))).string(), 48);
    const nlohmann::ordered_json fresh = alone.evaluate(configs[i], knobs, scene, name);
    EXPECT_FALSE(fresh["accuracy_reused"].get<bool>());
    EXPECT_EQ(comparable(nlohmann::json::array({row})), comparable(nlohmann::json::array({fresh}))) << name;
    for (const char* suffix : {".png", "_err.png"}) {
      const std::string a = readFile(d / "run" / "renders" / (name + suffix)),
                        b = readFile(d / ("alone" + std::to_string(i)) / "renders" / (name + suffix));
      EXPECT_FALSE(a.empty()) << name << suffix;
      EXPECT_EQ(a, b) << name << suffix;
    }
  }
}

TEST(Sweep, SceneKnobsLoadAndRenderTheSceneAgain) {
  // The evaluator keeps each scene file's scene as loaded and hw-cycle's setups, trace and
  // frame: a scene knob (the macropatch model, the tessellation level) must load and render
  // the scene again, and only a timing knob after it reuses. Every row must equal the row of
  // an evaluator that measured that point alone (keying the scene by its file and size alone
  // gave G0 the 144 primitives of G1, reused).
  const fs::path d = tempDir("scene_knobs");
  ReferenceCache cache((d / "cache").string());
  const std::string scene = kSrc + "/scenes/macropatch_g1.json";
  SweepEvaluator ev("hw-cycle", 1, cache);
  const auto knobs = [](const char* key, const nlohmann::ordered_json& v) {
    return nlohmann::ordered_json{{"scene.size", {64, 48}}, {key, v}};
  };
  HwConfig fewer;
  fewer.pipelines = 1;
  const std::string all = "setup, pixel trace, frame";
  const std::vector<std::tuple<nlohmann::ordered_json, HwConfig, std::string>> points = {
      {knobs("scene.macropatch", "G1"), HwConfig{}, ""},      {knobs("scene.macropatch", "G0"), HwConfig{}, ""},
      {knobs("scene.macropatch", "G0"), fewer, all},          {knobs("scene.tessellation_level", 8), HwConfig{}, ""},
      {knobs("scene.tessellation_level", 32), HwConfig{}, ""}, {knobs("scene.tessellation_level", 32), fewer, all}};
  std::vector<std::uint64_t> primitives;
  for (const auto& [k, cfg, expected] : points) {
    const nlohmann::ordered_json row = ev.evaluate(cfg, k, scene);
    EXPECT_EQ(row["datapath_reused"].get<std::string>(), expected) << k.dump();
    SweepEvaluator alone("hw-cycle", 1, cache);
    EXPECT_EQ(comparable(nlohmann::json::array({row})), comparable(nlohmann::json::array({alone.evaluate(cfg, k, scene)})))
        << k.dump();
    primitives.push_back(row["primitives"].get<std::uint64_t>());
  }
  EXPECT_GT(primitives[0], primitives[1]) << "G1 has more pieces than G0";
  EXPECT_LT(primitives[3], primitives[4]) << "a finer tessellation has more triangles";
}

TEST(Sweep, WithoutTheCacheEveryItemRendersItsReference) {
  // --no-cache: the reference is rendered for every item, also where the evaluator holds the
  // one it measured against before (the figures are reused only if both frames are equal).
  const fs::path d = tempDir("no_cache");
  ReferenceCache cache((d / "cache").string());
  cache.disable();
  SweepEvaluator ev("hw-cycle", 1, cache);
  const nlohmann::ordered_json knobs = {{"scene.size", {64, 48}}};
  HwConfig fewer;
  fewer.pipelines = 1;
  const std::string scene = kSrc + "/scenes/gallery.json";
  const nlohmann::ordered_json a = ev.evaluate(HwConfig{}, knobs, scene), b = ev.evaluate(fewer, knobs, scene);
  EXPECT_TRUE(a["reference_rendered"].get<bool>());
  EXPECT_TRUE(b["reference_rendered"].get<bool>());
  EXPECT_TRUE(b["accuracy_reused"].get<bool>());
  EXPECT_EQ(cache.renders(), 2u);
}

TEST(Sweep, AnImageWithNoRoomBesideThoseKeptIsMeasuredEveryTime) {
  // Room for one entry: two scenes in turn (a sweep's order), the first keeps its entry and
  // reuses it, the second has no room and is measured at every point; the figures are the
  // same either way.
  const fs::path d = tempDir("reuse_room");
  ReferenceCache cache((d / "cache").string());
  const nlohmann::ordered_json knobs = {{"scene.size", {64, 48}}};
  const std::string a = kSrc + "/scenes/gallery.json", b = kSrc + "/scenes/cylinders.json";
  SweepEvaluator ev("hw", 1, cache);
  ev.setMeasuredBytes(2 * std::size_t(64 * 48) * (3 + sizeof(double) + sizeof(std::int32_t)));  // one entry
  HwConfig cfg;
  for (int round = 0; round < 3; ++round)
    for (const std::string& scene : {a, b}) {
      const nlohmann::ordered_json row = ev.evaluate(cfg, knobs, scene);
      EXPECT_EQ(row["accuracy_reused"].get<bool>(), scene == a && round > 0) << scene << " round " << round;
      SweepEvaluator alone("hw", 1, cache);
      EXPECT_EQ(comparable(nlohmann::json::array({row})),
                comparable(nlohmann::json::array({alone.evaluate(cfg, knobs, scene)})))
          << scene;
    }
  // No room at all: nothing is kept, nothing reused.
  SweepEvaluator none("hw", 1, cache);
  none.setMeasuredBytes(0);
  for (int round = 0; round < 2; ++round) EXPECT_FALSE(none.evaluate(cfg, knobs, a)["accuracy_reused"].get<bool>());
}

TEST(Autosize, FindsTheExhaustiveOptimumOfASmallGrid) {
  const fs::path d = tempDir("autosize");
  const std::string scene = kSrc + "/scenes/gallery.json";
  SweepSpec spec = loadSweepSpec(write(d / "grid.json", R"({"format": "qacc-sweep/1", "engine": "hw", "scenes": [")" +
                                                           scene + R"("], "size": [96, 72], "thumbnail_width": 0,
    "axes": [{"key": "value_bits", "values": [32, 24, 20, 16]}, {"key": "normal_bits", "values": [16, 14]},
             {"key": "unit_frac_bits", "values": [14, 10, 6]}]})"));
  ReferenceCache cache((d / "cache").string());
  SweepEvaluator ev("hw", 0, cache);
  const SweepResults all = runSweep(spec, Shard{}, ev);
  const AccuracyTarget target = parseAccuracyTarget("wrong<=0.5%,psnr>=40");
  double bestGe = 1e300;
  std::string bestLabel;
  for (const auto& row : all.rows)
    if (target.meets(row) && row["gates_kge"].get<double>() < bestGe) {
      bestGe = row["gates_kge"].get<double>();
      bestLabel = row["label"].get<std::string>();
    }
  ASSERT_LT(bestGe, 1e300);
  AutosizeOptions o;
  o.scenes = {scene};
  o.target = target;
  o.keys = {"value_bits", "normal_bits", "unit_frac_bits"};
  o.values = {{"value_bits", {32, 24, 20, 16}}, {"normal_bits", {16, 14}}, {"unit_frac_bits", {14, 10, 6}}};
  o.knobs["scene.size"] = {96, 72};
  const AutosizeResult r = autosize(o, ev);
  ASSERT_TRUE(r.found);
  EXPECT_NEAR(r.gates_kge, bestGe, 1e-9) << "exhaustive optimum: " << bestLabel;
  EXPECT_LE(r.evaluations, all.rows.size());
  // The answer's colour error is its render's: the lowest PSNR over its one scene, the
  // exhaustive sweep's row of the same configuration (and at least what the target asks).
  int matched = 0;
  for (const auto& row : all.rows)
    if (row["config.value_bits"] == r.best.value_bits && row["config.normal_bits"] == r.best.normal_bits &&
        row["config.unit_frac_bits"] == r.best.unit_frac_bits) {
      EXPECT_EQ(jsonNumberValue(row["psnr_db"]), r.worst_psnr_db);
      EXPECT_EQ(r.worst_wrong_percent, row["wrong_percent"].get<double>());
      ++matched;
    }
  EXPECT_EQ(matched, 1);
  EXPECT_GE(r.worst_psnr_db, 40);
}

// The rows' non-finite figures ("inf", "-inf", "nan", as jsonNumber writes them) read back,
// and the answer's PSNR as both commands print it.
TEST(Autosize, ReadsAndPrintsTheRowsPsnrAsWritten) {
  for (const double v : {46.84, 0.0, 3.0, -2.5, double(INFINITY), -double(INFINITY)}) EXPECT_EQ(jsonNumberValue(jsonNumber(v)), v);
  EXPECT_TRUE(std::isnan(jsonNumberValue(jsonNumber(std::nan("")))));
  EXPECT_TRUE(std::isnan(jsonNumberValue(nlohmann::ordered_json())));       // a missing figure
  EXPECT_TRUE(std::isnan(jsonNumberValue(nlohmann::ordered_json("n/a"))));  // not a number
  EXPECT_EQ(lowestPsnrText(46.84), "lowest PSNR 46.8 dB");
  EXPECT_EQ(lowestPsnrText(INFINITY), "every image identical to the reference");
  EXPECT_EQ(lowestPsnrText(std::nan("")), "PSNR not measured");
}

TEST(CommandLine, FlagsAnEngineDoesNotReadAreRefused) {
  const fs::path d = tempDir("flags");
  const std::string scene = kSrc + "/scenes/cylinders.json --width 64 --height 48 -o " + (d / "x.png").string();
  const std::string cfg = kSrc + "/hw_model/configs/minimal.json";
  struct Case {
    std::string args, message;
  } cases[] = {{"--engine reference --config " + cfg, "--config is read by the accelerator engines"},
               {"--engine reference --level 8", "--level is read by the facets engine only"},
               {"--engine hw --level 8", "--level is read by the facets engine only"},
               {"--engine hw-cycle --shading pixel", "--shading is read by the facets engine only"},
               {"--engine facets --config " + cfg, "--config is read by the accelerator engines"}};
  for (const Case& c : cases) {
    const qacc::CommandRun r = run(qaccExe() + " render " + scene + " " + c.args);
    EXPECT_EQ(r.status, 1) << c.args << ": " << r.out;
    EXPECT_NE(r.out.find("qacc: error: " + c.message), std::string::npos) << c.args << ": " << r.out;
  }
  // --stats works for every engine; a configuration without a name is named after its file.
  const qacc::CommandRun ref = run(qaccExe() + " render " + scene + " --stats " + (d / "ref.json").string());
  ASSERT_EQ(ref.status, 0) << ref.out;
  std::ifstream in(d / "ref.json");
  EXPECT_EQ(nlohmann::json::parse(in)["engine"], "reference");
  const std::string named = write(d / "narrow16.json", R"({"format": "qacc-hw-config/1", "value_bits": 16})");
  const qacc::CommandRun hw = run(qaccExe() + " render " + scene + " --engine hw --config " + named + " --stats " + (d / "hw.json").string());
  ASSERT_EQ(hw.status, 0) << hw.out;
  EXPECT_NE(hw.out.find("hw [narrow16]"), std::string::npos) << hw.out;
  std::ifstream hin(d / "hw.json");
  const nlohmann::json st = nlohmann::json::parse(hin);
  EXPECT_EQ(st["config"], "narrow16");
  EXPECT_EQ(st["configuration"]["value_bits"], 16);
  EXPECT_EQ(st["configuration"]["delta_bits"], 64);
  EXPECT_TRUE(st["accuracy"].contains("wrong_percent"));
  EXPECT_TRUE(st["accuracy"].contains("depth_max_z24"));
}
