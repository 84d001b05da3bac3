// The exact CSG reference (raster/reference/csg_hit.h) against closed-form answers:
// areas, depths, volumes, the surface of a subtracted solid and coincident faces.
#include <gtest/gtest.h>

#include <cmath>
#include <string>

#include "modeling/loader/scene_loader.h"
#include "raster/reference/reference_renderer.h"
#include "tests/raster/notched_cube_scene.h"

using namespace qacc;

namespace {

// Orthographic camera on +z looking down -z (or along `eye`), `size` pixels square over
// `height` world units, near 1 and far 9 from an eye 5 units from the origin.
Scene orthoScene(const std::string& objects, int size, double height, const std::string& eye = "[0, 0, 5]",
                 const std::string& up = "[0, 1, 0]") {
  return parseScene(R"({"format": "qacc-scene/1", "image": {"width": )" + std::to_string(size) +
                        R"(, "height": )" + std::to_string(size) + R"(},
    "camera": {"type": "orthographic", "eye": )" + eye + R"(, "target": [0, 0, 0], "up": )" + up +
                        R"(, "height": )" + std::to_string(height) + R"(, "near": 1, "far": 9},
    "objects": [)" + objects + "]}",
                    "t.json", ".");
}

long long covered(const FrameBuffer& fb) {
  long long n = 0;
  for (std::size_t i = 0; i < fb.pixels(); ++i) n += fb.object[i] >= 0;
  return n;
}

// Distance from the eye's plane toward the target of an orthographic window depth.
double eyeDistance(double z) { return 1 + z * 8; }

const char* kSphereMinusCylinder = R"({"type": "csg", "op": "difference", "children": [
    {"type": "sphere", "radius": 1, "solid": true},
    {"type": "cylinder", "base": [0, 0, -2], "top": [0, 0, 2], "radius": 0.5, "solid": true}]})";

}  // namespace

TEST(CsgReference, SphereMinusCylinderAreaAndDepths) {
  const int N = 300;
  const double H = 2.4, px = H / N;
  const Scene s = orthoScene(kSphereMinusCylinder, N, H);
  const FrameBuffer fb = renderReference(s, 2);
  const double area = double(covered(fb)) * px * px;
  const double exact = M_PI * (1.0 - 0.25);
  EXPECT_NEAR(area / exact, 1.0, 2e-3) << area << " vs " << exact;
  // Depths on the ring: the sphere's front at (x, y) is z = sqrt(1 - x² - y²).
  for (int i = 0; i < 40; ++i) {
    const int x = N / 2 + 38 + i, y = N / 2 + 5;
    const double wx = (x + 0.5) * px - H / 2, wy = H / 2 - (y + 0.5) * px;
    const double r2 = wx * wx + wy * wy;
    const std::size_t pix = std::size_t(y) * N + std::size_t(x);
    if (r2 < 0.25 || r2 > 1) {
      EXPECT_EQ(fb.object[pix], -1) << x << "," << y;
      continue;
    }
    ASSERT_EQ(fb.object[pix], 0);
    EXPECT_EQ(fb.primitive[pix], 0);
    EXPECT_NEAR(5 - eyeDistance(fb.depth[pix]), std::sqrt(1 - r2), 1e-9);
  }
  // The hole: nothing at the centre.
  EXPECT_EQ(fb.object[std::size_t(N / 2) * N + N / 2], -1);
}

TEST(CsgReference, SubtractedSolidShowsItsSurfaceInTheHole) {
  // A bite out of the front of a sphere: the bite's inner surface shows in the hole.
  const int N = 200;
  const double H = 2.4, px = H / N;
  const Scene s = orthoScene(R"({"type": "csg", "op": "difference", "children": [
    {"type": "sphere", "radius": 1, "solid": true},
    {"type": "sphere", "center": [0, 0, 1], "radius": 0.5, "solid": true}]})",
                             N, H);
  const FrameBuffer fb = renderReference(s, 2);
  for (int k = 0; k < 30; ++k) {
    const int x = N / 2 + k, y = N / 2;
    const double wx = (x + 0.5) * px - H / 2, wy = H / 2 - (y + 0.5) * px;
    const double r2 = wx * wx + wy * wy;
    const std::size_t pix = std::size_t(y) * N + std::size_t(x);
    if (r2 > 0.2) continue;  // the bite's rim is at r² = 0.234
    EXPECT_EQ(fb.primitive[pix], 1);
    EXPECT_NEAR(5 - eyeDistance(fb.depth[pix]), 1 - std::sqrt(0.25 - r2), 1e-9);
  }
}

TEST(CsgReference, SteinmetzTricylinderSilhouetteDepthAndVolume) {
  // The intersection of three orthogonal unit cylinders: seen along z its silhouette is the
  // unit disc, its top at (x, y) is sqrt(1 - max(x², y²)), its volume 8 (2 - √2).
  const int N = 300;
  const double H = 2.4, px = H / N;
  const Scene s = orthoScene(R"({"type": "csg", "op": "intersection", "children": [
    {"type": "cylinder", "base": [0, 0, -2], "top": [0, 0, 2], "radius": 1, "solid": true},
    {"type": "cylinder", "base": [-2, 0, 0], "top": [2, 0, 0], "radius": 1, "solid": true},
    {"type": "cylinder", "base": [0, -2, 0], "top": [0, 2, 0], "radius": 1, "solid": true}]})",
                             N, H);
  const FrameBuffer fb = renderReference(s, 2);
  EXPECT_NEAR(double(covered(fb)) * px * px / M_PI, 1.0, 2e-3);
  double volume = 0, maxDepthError = 0;
  for (int y = 0; y < N; ++y)
    for (int x = 0; x < N; ++x) {
      const std::size_t pix = std::size_t(y) * N + std::size_t(x);
      if (fb.object[pix] < 0) continue;
      const double wx = (x + 0.5) * px - H / 2, wy = H / 2 - (y + 0.5) * px;
      const double top = 5 - eyeDistance(fb.depth[pix]);
      volume += 2 * top * px * px;  // symmetric about z = 0
      maxDepthError = std::max(maxDepthError, std::abs(top - std::sqrt(1 - std::max(wx * wx, wy * wy))));
    }
  EXPECT_LT(maxDepthError, 1e-9);
  EXPECT_NEAR(volume / (8 * (2 - std::sqrt(2.0))), 1.0, 2e-3);
}

TEST(CsgReference, CoincidentFacesNeitherShowNorVanish) {
  // A cube as the intersection of three slabs (quadrics x² <= 1, ...) minus a box (a solid
  // half-space clipped by 5 planes) that shares the cube's faces x = 1, y = 1 and z = 1 on
  // its corner octant [0, 1]³. Seen along each axis, every pixel over the octant must show
  // the box's inner face at 0 (its subtracted surface), every other pixel the cube at 1.
  const std::string objects = R"({"type": "csg", "op": "difference", "children": [
    {"type": "csg", "op": "intersection", "children": [
      {"type": "quadric", "matrix": [[1,0,0,0],[0,0,0,0],[0,0,0,0],[0,0,0,-1]], "solid": true},
      {"type": "quadric", "matrix": [[0,0,0,0],[0,1,0,0],[0,0,0,0],[0,0,0,-1]], "solid": true},
      {"type": "quadric", "matrix": [[0,0,0,0],[0,0,0,0],[0,0,1,0],[0,0,0,-1]], "solid": true}]},
    {"type": "plane", "point": [0, 0, 1], "normal": [0, 0, 1], "solid": true,
     "clip": [[1,0,0,-1],[-1,0,0,0],[0,1,0,-1],[0,-1,0,0],[0,0,-1,0]]}]})";
  const int N = 160;
  const double H = 3.2;
  const char* eyes[3] = {"[0, 0, 5]", "[5, 0, 0]", "[0, 5, 0]"};
  const char* ups[3] = {"[0, 1, 0]", "[0, 0, 1]", "[1, 0, 0]"};
  for (int v = 0; v < 3; ++v) {
    const Scene s = orthoScene(objects, N, H, eyes[v], ups[v]);
    const FrameBuffer fb = renderReference(s, 2);
    const Eigen::Matrix4d Minv = s.camera.worldToWindow(N, N).inverse();
    int wrong = 0;
    for (int y = 0; y < N; ++y)
      for (int x = 0; x < N; ++x) {
        const std::size_t pix = std::size_t(y) * N + std::size_t(x);
        const Eigen::Vector3d P = (Minv * Eigen::Vector4d(x + 0.5, y + 0.5, 0, 1)).hnormalized();
        // The two coordinates across the view and the depth coordinate of this view.
        const int axis = v == 0 ? 2 : v == 1 ? 0 : 1;
        double u = 0, w = 0;
        if (axis == 2) u = P.x(), w = P.y();
        if (axis == 0) u = P.y(), w = P.z();
        if (axis == 1) u = P.z(), w = P.x();
        const bool inCube = std::abs(u) < 1 && std::abs(w) < 1;
        const bool inNotch = u > 0 && u < 1 && w > 0 && w < 1;
        if (!inCube) {
          wrong += fb.object[pix] >= 0;
          continue;
        }
        const double expected = inNotch ? 0.0 : 1.0;
        const double got = 5 - eyeDistance(fb.depth[pix]);
        const bool ok = fb.object[pix] == 0 && std::abs(got - expected) < 1e-9 && (fb.primitive[pix] == 3) == inNotch;
        wrong += !ok;
      }
    EXPECT_EQ(wrong, 0) << "view " << v;
  }
}

TEST(CsgReference, CoincidentFacesLeaveNoSpeckles) {
  // The same notched cube turned and seen in perspective, where the shared faces reach the
  // pixel lines through different arithmetic (quadric roots, clip planes): no pixel may
  // show another primitive than its four neighbours when those agree (a speckle).
  for (const char* angles : {"[20, 35, 10]", "[-30, 15, 50]", "[45, 45, 0]"}) {
    const Scene s = parseScene(notchedCubeScene(angles), "t.json", ".");
    const FrameBuffer fb = renderReference(s, 2);
    EXPECT_EQ(countSpeckles(fb), 0) << angles;
    EXPECT_GT(fb.covered(), 5000u);
  }
}

TEST(CsgReference, ThreadCountDoesNotChangeTheImage) {
  const Scene s = orthoScene(kSphereMinusCylinder, 128, 2.4, "[3, 2, 4]");
  const FrameBuffer a = renderReference(s, 1), b = renderReference(s, 3);
  EXPECT_EQ(a.color.data, b.color.data);
  EXPECT_EQ(a.depth, b.depth);
  EXPECT_EQ(a.primitive, b.primitive);
}
