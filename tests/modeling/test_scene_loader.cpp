// Scene loading (design §6): strict refusal of bad input with file + JSON path + problem,
// valid scenes with the right counts, transforms / clips / materials applied.
#include <gtest/gtest.h>

#include <cstdio>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <regex>
#include <sstream>
#include <iterator>
#include <set>
#include <string>

#include <unistd.h>

#include "modeling/geometry/natural_quadrics.h"
#include "modeling/loader/object_registry.h"
#include "modeling/geometry/quadric_type.h"
#include "modeling/loader/scene_loader.h"
#include "tests/sanitized_build.h"

namespace fs = std::filesystem;
using namespace qacc;

namespace {

const char* kHead = R"("format": "qacc-scene/1",
  "camera": {"eye": [0, 0, 10], "target": [0, 0, 0]},)";

std::string sceneWith(const std::string& objects, const std::string& extra = "") {
  return std::string("{") + kHead + extra + "\n  \"objects\": [" + objects + "]}";
}

fs::path tempDir() {
  static fs::path dir = [] {
    fs::path d = fs::temp_directory_path() / ("qacc_scene_loader_" + std::to_string(::getpid()));
    fs::create_directories(d);
    return d;
  }();
  return dir;
}

Scene parse(const std::string& text) { return parseScene(text, "test.json", tempDir().string()); }

// Parses `text`, expects a SceneError naming test.json, exactly `path`, and `problem`.
void expectError(const std::string& text, const std::string& path, const std::string& problem) {
  SCOPED_TRACE(text);
  try {
    parse(text);
    ADD_FAILURE() << "accepted bad scene, expected error at " << path << ": " << problem;
  } catch (const SceneError& e) {
    const std::string msg = e.what();
    EXPECT_EQ(e.file(), "test.json") << msg;
    EXPECT_EQ(e.jsonPath(), path) << msg;
    EXPECT_NE(msg.find(problem), std::string::npos) << msg;
    EXPECT_EQ(msg.rfind("test.json: " + path + ": ", 0), 0u) << msg;
    // Every error of the scene's text gives its line and column: syntax errors where the parser
    // stopped, the others where the value their path names starts.
    static const std::regex located(R"(: JSON syntax error at line [0-9]+, column [0-9]+: |\(line [0-9]+, column [0-9]+\)$)");
    EXPECT_TRUE(std::regex_search(msg, located)) << msg;
  }
}

void writeFile(const fs::path& p, const std::string& text) {
  std::ofstream out(p);
  out << text;
}

}  // namespace

TEST(SceneLoader, MinimalSceneDefaults) {
  const Scene s = parse(sceneWith(R"({"type": "sphere", "radius": 1})"));
  EXPECT_EQ(s.name, "test");
  EXPECT_EQ(s.width, 640);
  EXPECT_EQ(s.height, 480);
  ASSERT_EQ(s.objects.size(), 1u);
  ASSERT_EQ(s.primitives.size(), 1u);
  EXPECT_EQ(s.objects[0].type, "sphere");
  EXPECT_EQ(s.objects[0].first, 0u);
  EXPECT_EQ(s.objects[0].count, 1u);
  ASSERT_EQ(s.materials.size(), 1u);
  EXPECT_EQ(s.primitives[0].material, 0);
  EXPECT_FALSE(s.primitives[0].solid);
  // No lights given: headlight + ambient.
  ASSERT_EQ(s.lights.size(), 2u);
  EXPECT_EQ(s.lights[0].type, Light::Type::Directional);
  EXPECT_NEAR(s.lights[0].direction.z(), -1.0, 1e-12);
  EXPECT_EQ(s.lights[1].type, Light::Type::Ambient);
}

TEST(SceneLoader, EmptyObjectListIsFine) {
  const Scene s = parse(sceneWith(""));
  EXPECT_TRUE(s.objects.empty());
  EXPECT_TRUE(s.primitives.empty());
}

TEST(SceneLoader, FullHeader) {
  const Scene s = parse(R"({
    "format": "qacc-scene/1", "name": "full", "description": "every section",
    "image": {"width": 320, "height": 200, "background": [0.1, 0.2, 0.3]},
    "camera": {"type": "orthographic", "eye": [0, 5, 0], "target": [0, 0, 0], "up": [0, 0, -1],
               "height": 4, "near": 0.5, "far": 20},
    "lights": [{"type": "directional", "direction": [0, -2, 0], "color": [1, 1, 1]},
               {"type": "point", "position": [1, 2, 3], "color": [2, 2, 2]},
               {"type": "ambient", "color": [0.05, 0.05, 0.05]}],
    "materials": {"red": {"color": [0.9, 0.1, 0.1], "specular": 0.5, "shininess": 10},
                  "default": {"color": [0.2, 0.2, 0.2]}},
    "objects": [{"type": "sphere", "radius": 1, "material": "red", "name": "ball"},
                {"type": "sphere", "radius": 1, "center": [3, 0, 0]}]})");
  EXPECT_EQ(s.name, "full");
  EXPECT_EQ(s.width, 320);
  EXPECT_EQ(s.height, 200);
  EXPECT_DOUBLE_EQ(s.background.z(), 0.3);
  EXPECT_EQ(s.camera.type, Camera::Type::Orthographic);
  EXPECT_DOUBLE_EQ(s.camera.height, 4);
  EXPECT_DOUBLE_EQ(s.camera.near, 0.5);
  EXPECT_DOUBLE_EQ(s.camera.far, 20);
  ASSERT_EQ(s.lights.size(), 3u);
  EXPECT_NEAR(s.lights[0].direction.y(), -1.0, 1e-12);  // normalised
  EXPECT_EQ(s.lights[1].type, Light::Type::Point);
  EXPECT_DOUBLE_EQ(s.lights[1].position.z(), 3);
  EXPECT_DOUBLE_EQ(s.lights[1].color.x(), 2);
  ASSERT_EQ(s.materials.size(), 2u);
  EXPECT_DOUBLE_EQ(s.materials[0].color.x(), 0.2);  // redefined default
  EXPECT_EQ(s.materials[1].name, "red");
  EXPECT_DOUBLE_EQ(s.materials[1].shininess, 10);
  EXPECT_EQ(s.primitives[0].material, 1);
  EXPECT_EQ(s.primitives[1].material, 0);
  EXPECT_EQ(s.objects[0].material, 1);
}

TEST(SceneLoader, EveryBuiltInTypeLoads) {
  const Scene s = parse(sceneWith(R"(
    {"type": "sphere", "center": [1, 2, 3], "radius": 2},
    {"type": "ellipsoid", "radii": [1, 2, 3]},
    {"type": "cylinder", "base": [0, 0, 0], "top": [0, 2, 0], "radius": 0.5, "solid": true},
    {"type": "cone", "apex": [0, 1, 0], "base": [0, 0, 0], "radius": 0.5},
    {"type": "paraboloid", "radius": 1, "height": 2},
    {"type": "paraboloid", "radii": [1, 2], "height": 2},
    {"type": "hyperboloid1", "radii": [1, 1, 1], "height": 2},
    {"type": "hyperboloid2", "radii": [1, 1, 0.5], "height": 3},
    {"type": "hyperbolic_paraboloid", "a": 1, "b": 1, "extent": 1},
    {"type": "elliptic_cylinder", "a": 1, "b": 0.5, "height": 2},
    {"type": "hyperbolic_cylinder", "a": 0.5, "b": 0.5, "extent": 2, "height": 2},
    {"type": "parabolic_cylinder", "p": 0.5, "extent": 2, "height": 2},
    {"type": "plane", "point": [0, -1, 0], "normal": [0, 1, 0], "clip": [[1, 0, 0, -1], [-1, 0, 0, -1]]},
    {"type": "quadric", "matrix": [[1,0,0,0],[0,1,0,0],[0,0,-1,0],[0,0,0,0]], "clip": [[0,0,1,-1],[0,0,-1,0]]},
    {"type": "triangle", "vertices": [[0, 0, 0], [1, 0, 0], [0, 1, 0]]},
    {"type": "triangle_mesh", "vertices": [[0,0,0],[1,0,0],[1,1,0],[0,1,0]], "triangles": [[0,1,2],[0,2,3]]})"));
  ASSERT_EQ(s.objects.size(), 16u);
  EXPECT_EQ(s.primitives.size(), 17u);  // the mesh has two facets
  for (std::size_t i = 0; i < s.objects.size(); ++i) {
    for (std::size_t k = 0; k < s.objects[i].count; ++k)
      EXPECT_EQ(s.primitives[s.objects[i].first + k].object, int(i));
  }
  EXPECT_EQ(s.objects[15].type, "triangle_mesh");
  EXPECT_EQ(s.objects[15].first, 15u);
  EXPECT_EQ(s.objects[15].count, 2u);
  // Sphere of radius 2 at (1, 2, 3): centre inside, a point at distance 2 on the surface.
  EXPECT_LT(s.primitives[0].quadric.eval({1, 2, 3}), 0);
  EXPECT_NEAR(s.primitives[0].quadric.eval({3, 2, 3}), 0, 1e-12);
  EXPECT_TRUE(s.primitives[2].solid);
  EXPECT_FALSE(s.primitives[3].solid);
  EXPECT_TRUE(s.primitives[14].isPlanar());
  // Registry knows at least these types.
  for (const char* t : {"sphere", "triangle_mesh", "pdb", "quadric"}) EXPECT_NE(findObjectBuilder(t), nullptr) << t;
  EXPECT_EQ(findObjectBuilder("teapot"), nullptr);
}

TEST(SceneLoader, TranslatedSphereCentreIsInside) {
  const Scene s = parse(sceneWith(R"({"type": "sphere", "radius": 1, "transform": {"translate": [5, -2, 1]}})"));
  const Quadric& q = s.primitives[0].quadric;
  EXPECT_LT(q.eval({5, -2, 1}), 0);
  EXPECT_GT(q.eval({0, 0, 0}), 0);
  EXPECT_NEAR(q.eval({6, -2, 1}), 0, 1e-12);
}

TEST(SceneLoader, RotationOrderIsXThenYThenZ) {
  // (1, 0, 0) rotated 90° about X stays put, then 90° about Y goes to (0, 0, -1).
  // The opposite order (Y then X) would give (0, 1, 0).
  const Scene s = parse(sceneWith(
      R"({"type": "sphere", "center": [1, 0, 0], "radius": 0.1, "transform": {"rotate_deg": [90, 90, 0]}})"));
  const Quadric& q = s.primitives[0].quadric;
  EXPECT_LT(q.eval({0, 0, -1}), 0);
  EXPECT_GT(q.eval({0, 1, 0}), 0);
  EXPECT_GT(q.eval({1, 0, 0}), 0);
}

TEST(SceneLoader, NonUniformScale) {
  const Scene s = parse(sceneWith(R"({"type": "sphere", "radius": 1, "transform": {"scale": [2, 1, 0.5]}})"));
  const Quadric& q = s.primitives[0].quadric;
  EXPECT_LT(q.eval({1.9, 0, 0}), 0);
  EXPECT_GT(q.eval({0, 1.1, 0}), 0);
  EXPECT_GT(q.eval({0, 0, 0.6}), 0);
  EXPECT_NEAR(q.eval({0, 0, 0.5}), 0, 1e-12);
  const Scene u = parse(sceneWith(R"({"type": "sphere", "radius": 1, "transform": {"scale": 3}})"));
  EXPECT_NEAR(u.primitives[0].quadric.eval({0, 3, 0}), 0, 1e-12);
}

TEST(SceneLoader, ClipIsAddedInTheLocalFrame) {
  const Scene s = parse(sceneWith(R"(
    {"type": "sphere", "radius": 1, "clip": [[0, 0, 1, 0]], "transform": {"translate": [0, 0, 10]}},
    {"type": "cylinder", "base": [0, 0, 0], "top": [0, 0, 2], "radius": 1, "clip": [[1, 0, 0, 0]]})"));
  ASSERT_EQ(s.primitives[0].clip.size(), 1u);
  // Local z <= 0 becomes world z <= 10.
  EXPECT_TRUE(s.primitives[0].clip[0].contains({0, 0, 9.5}));
  EXPECT_FALSE(s.primitives[0].clip[0].contains({0, 0, 10.5}));
  // The cylinder keeps its own two end planes and gets the extra one.
  ASSERT_EQ(s.primitives[1].clip.size(), 3u);
  EXPECT_TRUE(s.primitives[1].clip[2].contains({-0.5, 0, 1}));
  EXPECT_FALSE(s.primitives[1].clip[2].contains({0.5, 0, 1}));
}

TEST(SceneLoader, CylinderRotatedAboutX) {
  // Axis +z rotated +90° about X points along -y.
  const Scene s = parse(sceneWith(
      R"({"type": "cylinder", "base": [0, 0, 0], "top": [0, 0, 2], "radius": 0.5, "transform": {"rotate_deg": [90, 0, 0]}})"));
  const Primitive& p = s.primitives[0];
  EXPECT_LT(p.quadric.eval({0, -1, 0}), 0);
  EXPECT_GT(p.quadric.eval({0, 0, 1}), 0);
  bool inside = true;
  for (const auto& h : p.clip) inside = inside && h.contains({0, -1, 0});
  EXPECT_TRUE(inside);
  bool above = true;
  for (const auto& h : p.clip) above = above && h.contains({0, 1, 0});
  EXPECT_FALSE(above);
}

TEST(SceneLoader, LoadSceneResolvesRelativeFiles) {
  const fs::path dir = tempDir() / "rel";
  fs::create_directories(dir);
  writeFile(dir / "quad.obj", "v 0 0 0\nv 1 0 0\nv 1 1 0\nv 0 1 0\nf 1 2 3 4\n");
  writeFile(dir / "scene.json", sceneWith(R"({"type": "triangle_mesh", "file": "quad.obj"})"));
  const Scene s = loadScene((dir / "scene.json").string());
  EXPECT_EQ(s.file, (dir / "scene.json").string());
  EXPECT_EQ(s.name, "scene");
  EXPECT_EQ(s.primitives.size(), 2u);
}

TEST(SceneLoader, MissingSceneFile) {
  const std::string path = (tempDir() / "no_such_scene.json").string();
  try {
    loadScene(path);
    FAIL() << "missing file accepted";
  } catch (const SceneError& e) {
    EXPECT_EQ(e.file(), path);
    EXPECT_NE(std::string(e.what()).find("cannot open"), std::string::npos) << e.what();
  }
}

TEST(SceneLoader, PdbObjectAddsElementMaterials) {
  const fs::path pdb = tempDir() / "water.pdb";
  writeFile(pdb,
            "HETATM    1  O   HOH A   1       0.000   0.000   0.000  1.00  0.00           O\n"
            "HETATM    2  H1  HOH A   1       0.957   0.000   0.000  1.00  0.00           H\n"
            "HETATM    3  H2  HOH A   1      -0.240   0.927   0.000  1.00  0.00           H\n");
  const Scene s = parse(sceneWith(R"({"type": "pdb", "file": "water.pdb", "style": "ball_and_stick"},
                                     {"type": "pdb", "file": "water.pdb", "style": "spacefill", "material": "default"})"));
  // Ball and stick: 3 atoms + 2 O-H bonds split in two halves (different colours).
  EXPECT_EQ(s.objects[0].count, 7u);
  EXPECT_EQ(s.objects[1].count, 3u);
  ASSERT_EQ(s.materials.size(), 3u);
  EXPECT_EQ(s.materials[1].name, "pdb:O");
  EXPECT_EQ(s.materials[2].name, "pdb:H");
  EXPECT_EQ(s.primitives[0].material, 1);
  EXPECT_EQ(s.primitives[1].material, 2);
  for (std::size_t k = 0; k < 3; ++k) EXPECT_EQ(s.primitives[7 + k].material, 0);
  // Spacefill oxygen: van der Waals radius 1.52 Å.
  EXPECT_NEAR(s.primitives[7].quadric.eval({1.52, 0, 0}), 0, 1e-12);

  // center: the centroid moves to the origin; waters: false drops HOH (nothing left here).
  const Scene c = parse(sceneWith(R"({"type": "pdb", "file": "water.pdb", "style": "spacefill", "center": true,
                                      "atom_scale": 0.5})"));
  const Eigen::Vector3d centroid = Eigen::Vector3d(0.957 - 0.240, 0.927, 0) / 3;
  EXPECT_NEAR(c.primitives[0].quadric.eval(-centroid + Eigen::Vector3d(0.76, 0, 0)), 0, 1e-9);
  expectError(sceneWith(R"({"type": "pdb", "file": "water.pdb", "waters": false})"), "/objects/0/waters",
              "belongs to a water molecule");
  writeFile(tempDir() / "empty.pdb", "REMARK nothing\nEND\n");
  expectError(sceneWith(R"({"type": "pdb", "file": "empty.pdb"})"), "/objects/0/file", "no ATOM/HETATM records");
}

TEST(SceneLoader, BadInputIsRefusedWithPathAndProblem) {
  const std::string sphere = R"({"type": "sphere", "radius": 1})";
  // Top level.
  expectError("[]", "/", "a scene must be a JSON object");
  expectError(R"({"format": "qacc-scene/1", "objects": []})", "/", "missing required key 'camera'");
  expectError(R"({"format": "qacc-scene/2", "camera": {}, "objects": []})", "/format", "unsupported format");
  expectError(R"({"format": 1, "camera": {}, "objects": []})", "/format", "expected a string");
  expectError(sceneWith(sphere, R"("colour": 1,)"), "/colour", "unknown key 'colour'");
  expectError(std::string("{") + kHead + R"("objects": {}})", "/objects", "expected an array");
  // JSON syntax, NaN, duplicates, overflow.
  expectError("{\n  \"format\": \"qacc-scene/1\",\n  \"camera\": {,\n}", "/", "line 3, column");
  expectError(sceneWith(R"({"type": "sphere", "radius": NaN})"), "/", "JSON syntax error");
  expectError(sceneWith(R"({"type": "sphere", "radius": 1, "radius": 2})"), "/objects/0/radius", "duplicate key");
  expectError(sceneWith(R"({"type": "sphere", "radius": 1e999})"), "/objects/0/radius", "not finite");
  // Image.
  expectError(sceneWith(sphere, R"("image": {"width": 20000},)"), "/image/width", "integer in [1, 16384]");
  expectError(sceneWith(sphere, R"("image": {"width": 0},)"), "/image/width", "integer in [1, 16384]");
  expectError(sceneWith(sphere, R"("image": {"width": 640.5},)"), "/image/width", "expected an integer");
  expectError(sceneWith(sphere, R"("image": {"width": 16384, "height": 16384},)"), "/image", "exceeds the limit");
  expectError(sceneWith(sphere, R"("image": {"background": [2, 0, 0]},)"), "/image/background/0", "[0, 1]");
  expectError(sceneWith(sphere, R"("image": {"depth": 8},)"), "/image/depth", "unknown key");
  // Camera.
  const std::string objs = R"(, "objects": []})";
  auto cam = [&](const std::string& c) { return R"({"format": "qacc-scene/1", "camera": )" + c + objs; };
  expectError(cam(R"({"eye": [1, 1, 1], "target": [1, 1, 1]})"), "/camera/target", "must differ from eye");
  expectError(cam(R"({"eye": [0, 5, 0], "target": [0, 0, 0]})"), "/camera", "parallel");
  expectError(cam(R"({"eye": [0, 5, 0], "up": [0, 2, 0]})"), "/camera/up", "parallel");
  expectError(cam(R"({"fov_y_deg": 180})"), "/camera/fov_y_deg", "(0, 180)");
  expectError(cam(R"({"fov_y_deg": 0})"), "/camera/fov_y_deg", "(0, 180)");
  expectError(cam(R"({"near": 10, "far": 1})"), "/camera/far", "near must be smaller than far");
  expectError(cam(R"({"near": 0})"), "/camera/near", "positive");
  expectError(cam(R"({"type": "fisheye"})"), "/camera/type", "unknown camera type");
  expectError(cam(R"({"type": "orthographic", "fov_y_deg": 30})"), "/camera/fov_y_deg", "perspective cameras");
  expectError(cam(R"({"type": "orthographic", "height": -1})"), "/camera/height", "positive");
  expectError(cam(R"({"eye": [0, 0]})"), "/camera/eye", "expected 3 numbers, got 2");
  // Lights and materials.
  expectError(sceneWith(sphere, R"("lights": [{"type": "spot"}],)"), "/lights/0/type", "unknown light type");
  expectError(sceneWith(sphere, R"("lights": [{"type": "directional", "direction": [0, 0, 0]}],)"),
              "/lights/0/direction", "non-zero");
  expectError(sceneWith(sphere, R"("lights": [{"type": "point"}],)"), "/lights/0", "missing required key 'position'");
  expectError(sceneWith(sphere, R"("lights": [{"type": "ambient", "color": [-1, 0, 0]}],)"), "/lights/0/color/0",
              "non-negative");
  expectError(sceneWith(sphere, R"("materials": {"red": {"color": [1, 0]}},)"), "/materials/red/color",
              "expected 3 numbers");
  expectError(sceneWith(sphere, R"("materials": {"red": {"shininess": 0}},)"), "/materials/red/shininess", "positive");
  expectError(sceneWith(sphere, R"("materials": {"red": {"gloss": 1}},)"), "/materials/red/gloss", "unknown key");
  // Objects: common keys.
  expectError(sceneWith(R"({"radius": 1})"), "/objects/0", "missing required key 'type'");
  expectError(sceneWith(R"({"type": "teapot"})"), "/objects/0/type", "unknown object type 'teapot'");
  expectError(sceneWith(R"({"type": "sphere", "radius": 1, "colour": "red"})"), "/objects/0/colour", "unknown key");
  expectError(sceneWith(R"({"type": "sphere", "radius": 1, "material": "red"})"), "/objects/0/material",
              "unknown material 'red'");
  expectError(sceneWith(R"({"type": "sphere", "radius": 1, "solid": "yes"})"), "/objects/0/solid", "true or false");
  expectError(sceneWith(R"({"type": "sphere", "radius": 1, "transform": {"scale": 0}})"), "/objects/0/transform/scale",
              "non-zero");
  expectError(sceneWith(R"({"type": "sphere", "radius": 1, "transform": {"scale": [1, 0, 1]}})"),
              "/objects/0/transform/scale/1", "non-zero");
  expectError(sceneWith(R"({"type": "sphere", "radius": 1, "transform": {"scale": [1e-200, 1e-200, 1e-200]}})"),
              "/objects/0/transform/scale", "singular");
  expectError(sceneWith(R"({"type": "sphere", "radius": 1e-200})"), "/objects/0", "non-finite coefficients");
  expectError(sceneWith(R"({"type": "sphere", "radius": 1e300})"), "/objects/0", "degenerates to a constant");
  expectError(sceneWith(R"({"type": "sphere", "radius": 1, "transform": {"rotate": [0, 0, 0]}})"),
              "/objects/0/transform/rotate", "unknown key");
  expectError(sceneWith(R"({"type": "sphere", "radius": 1, "transform": {"translate": [0, 0, null]}})"),
              "/objects/0/transform/translate/2", "expected a number, got null");
  expectError(sceneWith(R"({"type": "sphere", "radius": 1, "clip": [[0, 0, 0, 1]]})"), "/objects/0/clip/0",
              "non-zero normal");
  expectError(sceneWith(R"({"type": "sphere", "radius": 1, "clip": [[0, 0, 1]]})"), "/objects/0/clip/0",
              "expected 4 numbers");
  // Objects: their own keys (second object, to check the index in the path).
  auto second = [&](const std::string& o) { return sceneWith(sphere + ", " + o); };
  expectError(second(R"({"type": "sphere", "center": [0, 0], "radius": 1})"), "/objects/1/center",
              "expected 3 numbers, got 2");
  expectError(second(R"({"type": "sphere", "radius": 0})"), "/objects/1/radius", "positive");
  expectError(second(R"({"type": "sphere", "radius": -2})"), "/objects/1/radius", "positive");
  expectError(second(R"({"type": "sphere", "radius": "1"})"), "/objects/1/radius", "expected a number");
  expectError(second(R"({"type": "sphere"})"), "/objects/1", "missing required key 'radius'");
  expectError(second(R"({"type": "ellipsoid", "radii": [1, 0, 1]})"), "/objects/1/radii/1", "positive");
  expectError(second(R"({"type": "cylinder", "base": [1, 1, 1], "top": [1, 1, 1], "radius": 1})"), "/objects/1/top",
              "must differ");
  expectError(second(R"({"type": "cone", "apex": [0, 0, 0], "base": [0, 0, 1], "radius": 0})"), "/objects/1/radius",
              "positive");
  expectError(second(R"({"type": "paraboloid", "radius": 1, "radii": [1, 1], "height": 1})"), "/objects/1/radii",
              "not both");
  expectError(second(R"({"type": "paraboloid", "height": 1})"), "/objects/1", "missing required key 'radius'");
  expectError(second(R"({"type": "hyperboloid2", "radii": [1, 1, 1], "height": 1})"), "/objects/1/height",
              "exceed 2 c");
  expectError(second(R"({"type": "hyperbolic_cylinder", "a": 1, "b": 1, "extent": 0.5, "height": 1})"),
              "/objects/1/extent", "exceed a");
  expectError(second(R"({"type": "plane", "normal": [0, 0, 0]})"), "/objects/1/normal", "non-zero");
  expectError(second(R"({"type": "quadric", "matrix": [[0,0,0,0],[0,0,0,0],[0,0,0,0],[0,0,0,0]]})"),
              "/objects/1/matrix", "all zero");
  expectError(second(R"({"type": "quadric", "matrix": [[1,2,0,0],[0,1,0,0],[0,0,1,0],[0,0,0,-1]]})"),
              "/objects/1/matrix/0/1", "not symmetric");
  expectError(second(R"({"type": "quadric", "matrix": [[1,0,0,0],[0,1,0,0],[0,0,1,0]]})"), "/objects/1/matrix",
              "4 rows of 4 numbers");
  expectError(second(R"({"type": "triangle", "vertices": [[0,0,0],[1,0,0]]})"), "/objects/1/vertices",
              "expected 3 vertices");
  expectError(second(R"({"type": "triangle", "vertices": [[0,0,0],[1,0,0],[2,0,0]]})"), "/objects/1/vertices",
              "degenerate");
  expectError(second(R"({"type": "triangle", "vertices": [[0,0,0],[1,0,0],[0,1,0]], "solid": true})"),
              "/objects/1/solid", "meaningless");
  expectError(second(R"({"type": "triangle_mesh", "vertices": [[0,0,0],[1,0,0],[0,1,0]], "triangles": [[0,1,3]]})"),
              "/objects/1/triangles/0/2", "integer in [0, 2]");
  expectError(second(R"({"type": "triangle_mesh", "vertices": [[0,0,0],[1,0,0],[0,1,0]], "triangles": [[0,1]]})"),
              "/objects/1/triangles/0", "expected 3 vertex indices");
  expectError(second(R"({"type": "triangle_mesh", "triangles": []})"), "/objects/1", "missing required key 'vertices'");
  expectError(second(R"({"type": "triangle_mesh", "file": "absent.obj"})"), "/objects/1/file", "cannot open");
  expectError(second(R"({"type": "pdb", "file": "absent.pdb"})"), "/objects/1/file", "cannot open");
  expectError(second(R"({"type": "pdb", "file": "x.pdb", "style": "cartoon"})"), "/objects/1/style",
              "unknown style");
  expectError(second(R"({"type": "pdb", "file": "x.pdb", "style": "spacefill", "bond_radius": 0.2})"),
              "/objects/1/bond_radius", "ball_and_stick style only");
}

// Mutations of a valid scene (every value replaced by values of the wrong type, size or
// sign; every key removed) either load or are refused with a SceneError naming the file:
// never another exception, never a crash.
TEST(SceneLoader, MutatedScenesNeverCrash) {
  const std::string base = R"({"format": "qacc-scene/1", "name": "m",
    "image": {"width": 64, "height": 48, "background": [0.1, 0.1, 0.1]},
    "camera": {"type": "perspective", "eye": [0, -5, 2], "target": [0, 0, 0], "up": [0, 0, 1], "fov_y_deg": 40,
               "near": 0.1, "far": 50},
    "lights": [{"type": "directional", "direction": [0, 1, -1], "color": [1, 1, 1]}, {"type": "ambient"}],
    "materials": {"red": {"color": [0.9, 0.1, 0.1], "specular": 0.3, "shininess": 16}},
    "objects": [
      {"type": "sphere", "center": [0, 0, 0], "radius": 1, "material": "red", "solid": true,
       "clip": [[0, 0, 1, -0.5]], "transform": {"translate": [1, 0, 0], "rotate_deg": [0, 0, 30], "scale": [1, 2, 1]}},
      {"type": "cone", "apex": [0, 0, 2], "base": [0, 0, 0], "radius": 0.5},
      {"type": "paraboloid", "radii": [1, 2], "height": 1},
      {"type": "hyperbolic_cylinder", "a": 0.5, "b": 0.5, "extent": 2, "height": 1},
      {"type": "quadric", "matrix": [[1,0,0,0],[0,1,0,0],[0,0,-1,0],[0,0,0,0]]},
      {"type": "triangle_mesh", "vertices": [[0,0,0],[1,0,0],[0,1,0]], "triangles": [[0,1,2]]}]})";
  const nlohmann::json doc = nlohmann::json::parse(base);
  const std::vector<nlohmann::json> replacements = {nullptr, "x", nlohmann::json::array(), nlohmann::json::object(),
                                                    -1, 0, 1e308, 2.5, true, nlohmann::json::array({1, 2})};
  // Every JSON pointer of the document.
  std::vector<nlohmann::json::json_pointer> pointers;
  const nlohmann::json flat = doc.flatten();
  for (auto it = flat.begin(); it != flat.end(); ++it) {
    nlohmann::json::json_pointer p(it.key());
    while (!p.empty()) {
      pointers.push_back(p);
      p = p.parent_pointer();
    }
  }
  int refused = 0, loaded = 0;
  auto attempt = [&](const nlohmann::json& j) {
    try {
      parse(j.dump());
      ++loaded;
    } catch (const SceneError& e) {
      EXPECT_EQ(e.file(), "test.json");
      ++refused;
    } catch (const std::exception& e) {
      ADD_FAILURE() << "unexpected exception " << e.what() << " for " << j.dump();
    }
  };
  for (const auto& p : pointers) {
    for (const auto& r : replacements) {
      nlohmann::json j = doc;
      j[p] = r;
      attempt(j);
    }
    nlohmann::json j = doc;  // remove the key or element
    const auto parent = p.parent_pointer();
    const std::string last = p.back();
    if (j[parent].is_object()) j[parent].erase(last);
    else j[parent].erase(std::size_t(std::stoul(last)));
    attempt(j);
  }
  EXPECT_GT(refused, 500);
  EXPECT_GT(loaded, 10);
}

TEST(SceneLoader, BadObjFileNamesItsLine) {
  writeFile(tempDir() / "bad.obj", "v 0 0 0\nv 1 0 0\nv 0 1 0\nf 1 2 7\n");
  expectError(sceneWith(R"({"type": "triangle_mesh", "file": "bad.obj"})"), "/objects/0/file", "bad.obj:4:");
  writeFile(tempDir() / "bad.pdb", "ATOM      1  CA  ALA A   1      1.0xx   0.000   0.000  1.00  0.00           C\n");
  expectError(sceneWith(R"({"type": "pdb", "file": "bad.pdb"})"), "/objects/0/file", "bad.pdb:1:");
}

TEST(SceneLoader, ShippedScenesLoad) {
  const fs::path dir = fs::path(QACC_SOURCE_DIR) / "scenes";
  if (!fs::exists(dir)) GTEST_SKIP() << "no scenes directory";
  int n = 0;
  for (const auto& entry : fs::directory_iterator(dir)) {
    if (entry.path().extension() != ".json" || leftOutOfSanitizedSweeps(entry.path().stem().string())) continue;
    SCOPED_TRACE(entry.path().string());
    try {
      const Scene s = loadScene(entry.path().string());
      EXPECT_FALSE(s.primitives.empty());
      ++n;
    } catch (const std::exception& e) {
      ADD_FAILURE() << e.what();
    }
  }
  EXPECT_GT(n, 0);
}

// The gallery holds the 9 non-degenerate real quadric types, each once, all solid and cut.
TEST(SceneLoader, GalleryHasTheNineQuadricTypes) {
  const Scene s = loadScene(std::string(QACC_SOURCE_DIR) + "/scenes/gallery.json");
  ASSERT_EQ(s.primitives.size(), 9u);
  std::set<QuadricType> types;
  for (const auto& p : s.primitives) {
    const QuadricType t = quadricType(p.quadric);
    EXPECT_TRUE(isNonDegenerate(t)) << quadricTypeName(t);
    types.insert(t);
    EXPECT_TRUE(p.solid);
    EXPECT_FALSE(p.clip.empty());
  }
  EXPECT_EQ(types.size(), 9u);
  EXPECT_EQ(s.width, 800);
  EXPECT_EQ(s.height, 600);
}

// Each natural type of the scene format gives the quadric type its name promises.
TEST(SceneLoader, NaturalTypesClassify) {
  const Scene s = parse(sceneWith(R"(
    {"type": "sphere", "radius": 2},
    {"type": "ellipsoid", "radii": [1, 2, 3]},
    {"type": "cylinder", "base": [0, 0, 0], "top": [1, 2, 3], "radius": 0.5},
    {"type": "cone", "apex": [1, 1, 1], "base": [0, 0, 0], "radius": 0.5},
    {"type": "paraboloid", "radii": [1, 2], "height": 2},
    {"type": "hyperboloid1", "radii": [1, 1, 1], "height": 2},
    {"type": "hyperboloid2", "radii": [1, 1, 0.5], "height": 3},
    {"type": "hyperbolic_paraboloid", "a": 1, "b": 2, "extent": 1},
    {"type": "elliptic_cylinder", "a": 1, "b": 0.5, "height": 2},
    {"type": "hyperbolic_cylinder", "a": 0.5, "b": 0.5, "extent": 2, "height": 2},
    {"type": "parabolic_cylinder", "p": 0.5, "extent": 2, "height": 2},
    {"type": "plane", "normal": [1, 1, 0]},
    {"type": "sphere", "radius": 1, "transform": {"translate": [3, 4, 5], "rotate_deg": [10, 20, 30], "scale": [1, 2, 3]}})"));
  const QuadricType expected[] = {
      QuadricType::Ellipsoid,           QuadricType::Ellipsoid,          QuadricType::EllipticCylinder,
      QuadricType::EllipticCone,        QuadricType::EllipticParaboloid, QuadricType::HyperboloidOneSheet,
      QuadricType::HyperboloidTwoSheets, QuadricType::HyperbolicParaboloid, QuadricType::EllipticCylinder,
      QuadricType::HyperbolicCylinder,  QuadricType::ParabolicCylinder,  QuadricType::Plane,
      QuadricType::Ellipsoid};
  ASSERT_EQ(s.primitives.size(), std::size(expected));
  for (std::size_t i = 0; i < s.primitives.size(); ++i)
    EXPECT_EQ(quadricType(s.primitives[i].quadric), expected[i])
        << i << ": " << quadricTypeName(quadricType(s.primitives[i].quadric));
}

// The command line refuses a bad scene with a non-zero status and a message naming the key.
TEST(SceneLoader, CliRefusesBadSceneNamingTheKey) {
  const fs::path scene = tempDir() / "bad_center.json";
  writeFile(scene, sceneWith(R"({"type":"sphere","center":[0,0],"radius":1})"));
  const fs::path err = tempDir() / "bad_center.err";
  const std::string cmd = std::string("\"") + QACC_EXE + "\" render \"" + scene.string() + "\" -o \"" +
                          (tempDir() / "bad_center.png").string() + "\" 2> \"" + err.string() + "\" > /dev/null";
  const int status = std::system(cmd.c_str());
  EXPECT_NE(status, 0);
  std::ifstream in(err);
  std::stringstream ss;
  ss << in.rdbuf();
  const std::string msg = ss.str();
  EXPECT_NE(msg.find("/objects/0/center"), std::string::npos) << msg;
  EXPECT_NE(msg.find("bad_center.json"), std::string::npos) << msg;
  EXPECT_FALSE(fs::exists(tempDir() / "bad_center.png"));
}
