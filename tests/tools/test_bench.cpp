// `qacc bench --json` (the fields docs/PERFORMANCE.md is kept from; --zoomed-fov, the zoomed
// view's build and frames beside the full one's) and `--no-accuracy`
// (render and batch: no reference render for the accuracy line; refused by engines that
// print none), end to end through the command line.
#include <gtest/gtest.h>

#include <nlohmann/json.hpp>

#include <filesystem>
#include <fstream>
#include <string>

#include "tests/tools/command_run.h"

using qacc::CommandRun;
using qacc::qaccCommand;
using qacc::runCommand;

namespace {

// Runs `qacc ARGS`; returns the exit status and the output (stdout and stderr).
int runQacc(const std::string& args, std::string& text) {
  const CommandRun r = runCommand(qaccCommand(args) + " 2>&1");
  text = r.out;
  return r.status;
}

const std::string kScenes = std::string(QACC_SOURCE_DIR) + "/scenes/";

}  // namespace

TEST(BenchCommand, JsonHasEveryFieldPerSceneAndThreadCount) {
  const std::string json = (std::filesystem::path(QACC_BINARY_DIR) / "bench_test.json").string();
  std::filesystem::remove(json);
  std::string text;
  ASSERT_EQ(runQacc("bench " + kScenes + "torus.json --width 64 --height 48 --repeat 1 --threads 1,2 --json " + json, text),
            0)
      << text;
  std::ifstream in(json);
  ASSERT_TRUE(in) << text;
  const nlohmann::json doc = nlohmann::json::parse(in);
  EXPECT_FALSE(doc.at("machine").at("cpu_model").get<std::string>().empty());
  EXPECT_GE(doc.at("machine").at("cores").get<int>(), 1);
  ASSERT_EQ(doc.at("runs").size(), 2u);
  int threads = 1;
  for (const auto& r : doc.at("runs")) {
    EXPECT_EQ(r.at("scene"), "torus");
    EXPECT_EQ(r.at("threads").get<int>(), threads++);
    for (const char* k : {"ref_ms", "hw_ms", "hw_cycle_ms", "loop_cycles_per_second", "tested_pixels_per_second"})
      EXPECT_GT(r.at(k).get<double>(), 0.0) << k;
    EXPECT_GT(r.at("cycles").get<std::uint64_t>(), 0u);
    EXPECT_EQ(r.at("simulator_clock"), "items") << "the default configuration's main pass";
    // Each engine's best frame carries the page faults taken during it (a count, maybe 0).
    for (const char* k : {"ref_page_faults", "hw_page_faults", "hw_cycle_page_faults"})
      EXPECT_GE(r.at(k).get<long>(), 0) << k;
  }
  // The same frame on one and two threads: the same cycle count.
  EXPECT_EQ(doc["runs"][0]["cycles"], doc["runs"][1]["cycles"]);
  ASSERT_EQ(doc.at("scaling").size(), 1u);
  EXPECT_GT(doc["scaling"][0].at("hw_speedup").get<double>(), 0.0);
  EXPECT_NE(text.find("1 -> 2 threads"), std::string::npos) << text;
  EXPECT_NE(text.find("hw-cycle's simulator clock: items"), std::string::npos) << text;
}

TEST(BenchCommand, ZoomedFovBenchesTheZoomedViewBesideTheFullOne) {
  const std::string json = (std::filesystem::path(QACC_BINARY_DIR) / "bench_zoomed_test.json").string();
  std::filesystem::remove(json);
  std::string text;
  ASSERT_EQ(runQacc("bench " + kScenes + "torus.json --width 64 --height 48 --repeat 1 --threads 1 --no-cycle " +
                        "--zoomed-fov 4 --json " + json, text),
            0)
      << text;
  std::ifstream in(json);
  ASSERT_TRUE(in) << text;
  const nlohmann::json doc = nlohmann::json::parse(in);
  ASSERT_EQ(doc.at("runs").size(), 2u);
  const nlohmann::json &full = doc["runs"][0], &zoomed = doc["runs"][1];
  EXPECT_EQ(full.at("view"), "full");
  EXPECT_EQ(zoomed.at("view"), "zoomed");
  EXPECT_EQ(doc.at("zoomed_fov_deg").get<double>(), 4.0);
  // The zoomed view culls most of the torus's 1660 pieces; each view's build is timed.
  EXPECT_EQ(full.at("primitives").get<std::size_t>(), 1660u);
  EXPECT_LT(zoomed.at("primitives").get<std::size_t>(), 400u);
  for (const auto* r : {&full, &zoomed}) EXPECT_GT(r->at("build_ms").get<double>(), 0.0);
  EXPECT_NE(text.find("build ms"), std::string::npos) << text;
  EXPECT_NE(text.find("zoomed"), std::string::npos) << text;
}

TEST(BenchCommand, ZoomedFovRefusesAnOrthographicCamera) {
  const std::filesystem::path scene = std::filesystem::path(QACC_BINARY_DIR) / "bench_ortho.json";
  std::ofstream(scene) << R"({"format": "qacc-scene/1", "camera": {"type": "orthographic"}, "objects": []})";
  std::string text;
  const int status = runQacc(
      "bench " + scene.string() + " --width 16 --height 16 --repeat 1 --threads 1 --no-cycle --zoomed-fov 4", text);
  EXPECT_EQ(status, 1) << text;
  EXPECT_NE(text.find("bench_ortho.json: /camera/type: --zoomed-fov needs a perspective camera"), std::string::npos)
      << text;
}

TEST(NoAccuracy, SkipsTheAccuracyLineOfTheHwEngines) {
  const std::string out = (std::filesystem::path(QACC_BINARY_DIR) / "no_accuracy.png").string();
  const std::string render = "render " + kScenes + "torus.json --width 64 --height 48 -o " + out + " --engine ";
  std::string with, without;
  ASSERT_EQ(runQacc(render + "hw", with), 0) << with;
  EXPECT_NE(with.find("accuracy vs reference"), std::string::npos) << with;
  ASSERT_EQ(runQacc(render + "hw-cycle --no-accuracy", without), 0) << without;
  EXPECT_EQ(without.find("accuracy vs reference"), std::string::npos) << without;
  const std::string dir = (std::filesystem::path(QACC_BINARY_DIR) / "no_accuracy_batch").string();
  const std::string batch = "batch " + kScenes + "torus.json --width 64 --height 48 --out " + dir + " --engine hw";
  ASSERT_EQ(runQacc(batch, with), 0) << with;
  EXPECT_NE(with.find("accuracy vs reference"), std::string::npos) << with;
  ASSERT_EQ(runQacc(batch + " --no-accuracy", without), 0) << without;
  EXPECT_EQ(without.find("accuracy vs reference"), std::string::npos) << without;
}

TEST(NoAccuracy, RefusedByEnginesWithoutAnAccuracyLine) {
  std::string text;
  const std::string out = (std::filesystem::path(QACC_BINARY_DIR) / "no_accuracy_ref.png").string();
  EXPECT_NE(runQacc("render " + kScenes + "torus.json --width 64 --height 48 -o " + out +
                        " --engine reference --no-accuracy", text),
            0);
  EXPECT_NE(text.find("qacc: error: --no-accuracy"), std::string::npos) << text;
}
