// The command line as a careless user meets it (issue 14): every error is one line
// "qacc: error: ..." with exit status 1, within seconds, whatever the input.
#include <gtest/gtest.h>

#include <unistd.h>

#include <cstdio>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <string>

#include "tests/sanitized_build.h"
#include "tests/tools/command_run.h"

namespace fs = std::filesystem;

namespace {

fs::path tempDir() {
  static fs::path dir = [] {
    fs::path d = fs::temp_directory_path() / ("qacc_cli_errors_" + std::to_string(::getpid()));
    fs::create_directories(d);
    return d;
  }();
  return dir;
}

struct CliRun {
  int status = -1;
  std::string err;
};

// Runs `qacc ARGS` (60 s at most) and returns its exit status and standard error.
CliRun runQacc(const std::string& args) {
  const qacc::CommandRun c = qacc::runCommand("timeout 60 " + qacc::qaccCommand(args) + " 2>&1 >/dev/null");
  return {c.status, c.out};
}

void expectError(const CliRun& r, const std::string& needle) {
  EXPECT_EQ(r.status, 1) << r.err;
  EXPECT_EQ(r.err.rfind("qacc: error: ", 0), 0u) << r.err;
  EXPECT_NE(r.err.find(needle), std::string::npos) << r.err;
}

fs::path writeScene(const std::string& name, const std::string& objects) {
  const fs::path p = tempDir() / name;
  std::ofstream(p) << R"({"format": "qacc-scene/1", "image": {"width": 32, "height": 24},
  "camera": {"eye": [0, 0, 10], "target": [0, 0, 0]}, "objects": [)" << objects << "]}";
  return p;
}

}  // namespace

// CLI11's own errors exited 105/106 without the prefix.
TEST(CliErrors, ParseErrorsHaveThePrefixAndStatus1) {
  expectError(runQacc("render"), "scene is required");
  expectError(runQacc("render a.json -o x.png --threads 0"), "--threads");
  expectError(runQacc("render a.json -o x.png --no-such-flag"), "--no-such-flag");
  expectError(runQacc("no-such-command"), "subcommand");
}

// --level 0 and --level -3 silently became 128 while --level 1 was refused.
TEST(CliErrors, LevelOutOfRangeIsRefused) {
  const fs::path s = writeScene("level.json", R"({"type": "sphere", "center": [0,0,0], "radius": 1})");
  for (const char* level : {"0", "-3", "1"})
    expectError(runQacc("render " + s.string() + " -o " + (tempDir() / "l.png").string() + " --engine facets --level " + level),
                "--level");
}

// A scene path that is a directory reported "JSON syntax error at line 1, column 1";
// `qacc info /dev/zero` read forever.
TEST(CliErrors, InputThatIsNotAFile) {
  expectError(runQacc("info " + tempDir().string()), "scene file is a directory");
  expectError(runQacc("info /dev/zero --max-input-mb 4"), "--max-input-mb");
}

// `batch` stopped at the first bad scene: now it renders the others and fails at the end.
TEST(CliErrors, BatchGoesOnAfterABadScene) {
  const fs::path good = writeScene("good.json", R"({"type": "sphere", "center": [0,0,0], "radius": 1})");
  const fs::path bad = writeScene("bad.json", R"({"type": "sphere", "center": [0,0], "radius": 1})");
  const fs::path out = tempDir() / "batch_out";
  const CliRun r = runQacc("batch " + bad.string() + " " + good.string() + " --out " + out.string());
  EXPECT_EQ(r.status, 1) << r.err;
  EXPECT_NE(r.err.find("qacc: error: " + bad.string() + ": /objects/0/center"), std::string::npos) << r.err;
  EXPECT_NE(r.err.find("1 of 2 scenes"), std::string::npos) << r.err;
  EXPECT_TRUE(fs::exists(out / "good.png"));
}

// Work over the limits is refused before it starts, naming the option that raises it.
TEST(CliErrors, LimitsNameTheirOptions) {
  const fs::path s = writeScene("many.json", R"({"type": "sphere", "center": [0,0,0], "radius": 1},
                                             {"type": "sphere", "center": [1,0,0], "radius": 1})");
  expectError(runQacc("info " + s.string() + " --max-primitives 1"), "--max-primitives");
  expectError(runQacc("render " + s.string() + " -o " + (tempDir() / "f.png").string() +
                   " --engine facets --level 64 --max-triangles 100"),
              "--max-triangles");
}

// The facets of the B-spline volume (41 839 pieces x level 128) took 126 s of CPU and 3.5 GB:
// the default triangle limit refuses them before tessellating, and says how to raise it.
TEST(CliErrors, VolumeFacetsAtTheDefaultLevelAreRefusedByTheTriangleLimit) {
  // The volume's load alone passes the 60 s of runQacc() under ASan (tests/sanitized_build.h).
  if (leftOutOfSanitizedSweeps("bspline_volume_g1")) GTEST_SKIP() << "bspline_volume_g1 is checked in Release";
  const std::string scene = std::string(QACC_SOURCE_DIR) + "/scenes/bspline_volume_g1.json";
  const CliRun r = runQacc("render " + scene + " -o " + (tempDir() / "v.png").string() +
                        " --engine facets --width 160 --height 120");
  EXPECT_EQ(r.status, 1) << r.err;
  EXPECT_NE(r.err.find("qacc: error: "), std::string::npos) << r.err;
  EXPECT_NE(r.err.find("above the limit of 4000000 (raise it with --max-triangles)"), std::string::npos) << r.err;
}
