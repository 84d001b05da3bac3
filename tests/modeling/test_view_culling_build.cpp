// Build time falls with the view (modeling/loader/view_culling.h, issue 13): the modelers
// test their pieces against the view volume before building them, so a zoomed view builds
// fewer pieces, and faster, than the full one. The benchmark of docs/SCENES.md "View
// culling": the torus (degree reduction), the B-spline height field and volume, the
// molecule and a 65 536 triangle mesh (an OBJ sphere written here), each loaded with its
// own camera and with the field of view narrowed to 4 degrees; it prints the load time
// (best of two; wall time, on whatever load the machine has), the primitives emitted and
// the modeler's own account of what it built. Asserted: the zoomed view emits fewer
// primitives and its modeler reports pieces (or cells) it did not build; the pixel identity
// of culled and unculled renders is tests/tools/test_view_culling.cpp.
#include <gtest/gtest.h>

#include <chrono>
#include <cmath>
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <unistd.h>
#include <string>

#include <nlohmann/json.hpp>

#include "modeling/loader/scene_loader.h"
#include "tests/sanitized_build.h"

using namespace qacc;
namespace fs = std::filesystem;

namespace {

// A UV sphere of radius 1 as an OBJ: `rings` x `segments` quads, two triangles each.
void writeSphereObj(const fs::path& path, int rings, int segments) {
  std::ofstream out(path);
  const double pi = std::acos(-1.0);
  for (int i = 0; i <= rings; ++i)
    for (int j = 0; j < segments; ++j) {
      const double t = pi * i / rings, p = 2 * pi * j / segments;
      out << "v " << std::sin(t) * std::cos(p) << ' ' << std::sin(t) * std::sin(p) << ' ' << std::cos(t) << '\n';
    }
  auto id = [&](int i, int j) { return i * segments + (j % segments) + 1; };
  for (int i = 0; i < rings; ++i)
    for (int j = 0; j < segments; ++j) {
      out << "f " << id(i, j) << ' ' << id(i + 1, j) << ' ' << id(i + 1, j + 1) << '\n';
      out << "f " << id(i, j) << ' ' << id(i + 1, j + 1) << ' ' << id(i, j + 1) << '\n';
    }
}

struct Load {
  double seconds = 1e300;
  std::size_t primitives = 0;
  std::string note;
};

Load load(const nlohmann::json& doc, const fs::path& file, int repeat) {
  Load best;
  for (int r = 0; r < repeat; ++r) {
    const auto t0 = std::chrono::steady_clock::now();
    const Scene s = parseScene(doc.dump(), file.string(), file.parent_path().string());
    best.seconds = std::min(best.seconds, std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count());
    best.primitives = s.primitives.size();
    best.note = s.objects.empty() ? "" : s.objects[0].note;
  }
  return best;
}

}  // namespace

TEST(ViewCullingBuild, ZoomedViewsBuildFewerPiecesThanFullViews) {
  const fs::path scenes = fs::path(QACC_SOURCE_DIR) / "scenes";
  const fs::path dir = fs::temp_directory_path() / ("qacc_view_cull_build_" + std::to_string(::getpid()));
  fs::create_directories(dir);
  writeSphereObj(dir / "sphere.obj", 128, 256);
  const nlohmann::json mesh = nlohmann::json::parse(R"js({"format": "qacc-scene/1", "name": "mesh_sphere",
    "image": {"width": 640, "height": 480},
    "camera": {"type": "perspective", "eye": [0, -4, 1], "target": [0, 0, 0], "up": [0, 0, 1], "fov_y_deg": 40,
               "near": 0.5, "far": 20},
    "objects": [{"type": "triangle_mesh", "file": "sphere.obj"}]})js");

  struct Case {
    std::string name;
    nlohmann::json doc;
    fs::path file;
    int repeat;
  };
  std::vector<Case> cases;
  for (const char* s : {"torus", "bspline_g1", "bspline_volume_g1", "molecule"}) {
    if (leftOutOfSanitizedSweeps(s)) continue;
    const fs::path f = scenes / (std::string(s) + ".json");
    // Each load twice for its time (the best is printed), once under the sanitizers, whose
    // times mean nothing (tests/sanitized_build.h).
    cases.push_back({s, nlohmann::json::parse(readSceneText(f.string())), f,
                     std::string(s) == "bspline_volume_g1" || kSanitizedBuild ? 1 : 2});
  }
  cases.push_back({"mesh (65 536 triangles)", mesh, dir / "mesh.json", kSanitizedBuild ? 1 : 2});

  std::printf("%-24s %-7s %9s %10s  %s\n", "scene", "view", "load s", "primitives", "modeler's note");
  for (const Case& c : cases) {
    if (c.name == "molecule" && !fs::exists("/usr/share/pymol/data/tut/1hpv.pdb")) {
      std::printf("%-24s skipped: /usr/share/pymol/data/tut/1hpv.pdb is not installed\n", c.name.c_str());
      continue;
    }
    nlohmann::json zoomedDoc = c.doc;
    zoomedDoc["camera"]["fov_y_deg"] = 4;
    const Load full = load(c.doc, c.file, c.repeat), zoomed = load(zoomedDoc, c.file, c.repeat);
    std::printf("%-24s %-7s %9.3f %10zu  %s\n", c.name.c_str(), "full", full.seconds, full.primitives,
                full.note.c_str());
    std::printf("%-24s %-7s %9.3f %10zu  %s\n", c.name.c_str(), "zoomed", zoomed.seconds, zoomed.primitives,
                zoomed.note.c_str());
    std::fflush(stdout);
    EXPECT_LT(zoomed.primitives, full.primitives) << c.name;
    // The modeler itself skipped work: "K of N pieces outside the view not built" (molecule,
    // mesh), "M outside the view" cells (degree reduction), "M tetrahedra and regions outside
    // the view" (volumes), with M > 0.
    const std::size_t at = zoomed.note.find(" outside the view");
    ASSERT_NE(at, std::string::npos) << c.name << ": " << zoomed.note;
    std::size_t start = zoomed.note.rfind(", ", at);
    start = start == std::string::npos ? 0 : start + 2;
    EXPECT_GT(std::stoul(zoomed.note.substr(start)), 0u) << c.name << ": " << zoomed.note;
  }
  fs::remove_all(dir);
}
