// Screen boxes of window-space primitives never miss a visible pixel, and are tight.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <random>
#include <string>

#include "modeling/scene/camera.h"
#include "modeling/geometry/natural_quadrics.h"
#include "modeling/geometry/primitive_bounds.h"
#include "modeling/loader/scene_loader.h"
#include "raster/pixel/pixel_hit.h"
#include "raster/pixel/window_primitive.h"

using namespace qacc;

namespace {

// Every pixel where the primitive is visible, by brute force over the whole screen, must
// lie inside its box. Returns the number of visible pixels.
long long checkBox(const Primitive& prim, const Camera& cam, int W, int H, ScreenBox* boxOut = nullptr,
                   ScreenBox* visibleOut = nullptr) {
  const Eigen::Matrix4d M = cam.worldToWindow(W, H), Minv = M.inverse();
  const WindowPrimitive w = toWindow(prim, 0, M, Minv, W, H);
  long long visible = 0;
  ScreenBox seen{W, H, 0, 0};
  for (int y = 0; y < H; ++y)
    for (int x = 0; x < W; ++x) {
      PixelHit h;
      if (!pixelHit(w, x + 0.5, y + 0.5, h)) continue;
      ++visible;
      seen = {std::min(seen.x0, x), std::min(seen.y0, y), std::max(seen.x1, x + 1), std::max(seen.y1, y + 1)};
      EXPECT_TRUE(x >= w.box.x0 && x < w.box.x1 && y >= w.box.y0 && y < w.box.y1)
          << "pixel " << x << "," << y << " outside box [" << w.box.x0 << "," << w.box.x1 << ")x[" << w.box.y0
          << "," << w.box.y1 << ")";
    }
  if (boxOut) *boxOut = w.box;
  if (visibleOut) *visibleOut = seen;
  return visible;
}

}  // namespace

TEST(WindowPrimitive, BoxesContainEveryVisiblePixel) {
  std::mt19937 rng(11);
  std::uniform_real_distribution<double> u(-2, 2), r(0.2, 1.0);
  const int W = 160, H = 120;
  for (int trial = 0; trial < 60; ++trial) {
    Camera cam;
    cam.eye = {u(rng) * 3, u(rng) * 3, 6 + u(rng)};
    if (trial % 5 == 0) {
      cam.type = Camera::Type::Orthographic;
      cam.height = 6;
    }
    const Eigen::Vector3d a(u(rng), u(rng), u(rng)), b(u(rng), u(rng), u(rng));
    std::vector<Primitive> prims = {
        makeCylinder(a, b, r(rng)), makeCone(a, b, r(rng)), makeSphere(a, r(rng)),
        makeHyperboloid1({r(rng), r(rng), r(rng)}, 2).transformed(placement(a, {u(rng) * 40, u(rng) * 40, 0}, {1, 1, 1})),
        makeHyperboloid2({r(rng), r(rng), r(rng)}, 3).transformed(placement(a, {u(rng) * 40, 0, u(rng) * 40}, {1, 1, 1})),
        makeParaboloid(r(rng), r(rng), 1.5).transformed(placement(a, {u(rng) * 40, 0, 0}, {1, 1, 1})),
        makeHyperbolicParaboloid(r(rng), r(rng), 1).transformed(placement(a, {0, u(rng) * 40, 0}, {1, 1, 1})),
        makeTriangle(a, b, Eigen::Vector3d(u(rng), u(rng), u(rng))),
    };
    for (std::size_t k = 0; k < prims.size(); ++k) {
      Primitive& p = prims[k];
      SCOPED_TRACE("trial " + std::to_string(trial) + " primitive " + std::to_string(k));
      p.clip.push_back(HalfSpace(Eigen::Vector4d(u(rng), u(rng), u(rng), u(rng) * 0.5)));
      for (bool solid : {false, true}) {
        p.solid = solid;
        SCOPED_TRACE(solid ? "solid" : "surface");
        checkBox(p, cam, W, H);
      }
    }
  }
}

TEST(WindowPrimitive, FiniteCylinderBoxIsTight) {
  // A thin finite cylinder: its contour conic and its slab are both unbounded on screen,
  // but the box of the piece itself must be close to its projected extent.
  Camera cam;
  cam.eye = {0, 0, 10};
  const int W = 400, H = 300;
  const Primitive p = makeCylinder({-1, -0.5, 0}, {1, 0.5, 0}, 0.1);
  ScreenBox box, seen;
  const long long visible = checkBox(p, cam, W, H, &box, &seen);
  EXPECT_GT(visible, 500);
  // The box is the visible pixels' own bounding box, widened by at most 2 pixels a side.
  EXPECT_LE(seen.x0 - box.x0, 2);
  EXPECT_LE(seen.y0 - box.y0, 2);
  EXPECT_LE(box.x1 - seen.x1, 2);
  EXPECT_LE(box.y1 - seen.y1, 2);
}

TEST(WindowPrimitive, ConicBoxOfAnEllipseIsExact) {
  // x²/9 + y²/4 <= 1 around (50, 40): Δ = 1 − (x−50)²/9 − (y−40)²/4.
  Conic d;
  d.A = -1.0 / 9;
  d.C = -1.0 / 4;
  d.D = 50.0 / 9;
  d.E = 40.0 / 4;
  d.F = 1 - 2500.0 / 9 - 1600.0 / 4;
  const ScreenBox b = conicBox(d, 200, 200);
  // Centres i + 0.5 in [47, 53] x [38, 42] → indices 47..52 and 38..41, widened by one.
  EXPECT_EQ(b.x0, 46);
  EXPECT_EQ(b.x1, 54);
  EXPECT_EQ(b.y0, 37);
  EXPECT_EQ(b.y1, 43);
}

// The depth range completed from the screen box's own candidates (toWindow's extentXY, the
// z candidates alone added) is the range computed from scratch, bit for bit, and asking
// for the extent changes no box: every primitive of scenes with spheres, clipped
// cylinders and cones, solids, planar facets, degree-reduced patches and csg leaves.
TEST(WindowPrimitive, DepthRangeFromTheBoxCandidatesEqualsTheFullOne) {
  int planar = 0, solid = 0, checked = 0;
  for (const char* name : {"sphereflake", "molecule", "gallery", "cylinders", "vase_g0", "character", "quartic",
                           "csg/csg_mechanical"}) {
    Scene scene = loadScene(std::string(QACC_SOURCE_DIR) + "/scenes/" + name + ".json");
    for (const auto& [W, H] : {std::pair{160, 120}, std::pair{1920, 1080}}) {
      const Eigen::Matrix4d M = scene.camera.worldToWindow(W, H), Minv = M.inverse();
      for (std::size_t i = 0; i < scene.primitives.size(); ++i) {
        const Primitive& prim = scene.primitives[i];
        Eigen::AlignedBox3d ext;
        const WindowPrimitive w = toWindow(prim, int(i), M, Minv, W, H, &ext);
        const WindowPrimitive plain = toWindow(prim, int(i), M, Minv, W, H);
        ASSERT_EQ(w.box.x0, plain.box.x0) << name << " primitive " << i;
        ASSERT_EQ(w.box.y0, plain.box.y0) << name << " primitive " << i;
        ASSERT_EQ(w.box.x1, plain.box.x1) << name << " primitive " << i;
        ASSERT_EQ(w.box.y1, plain.box.y1) << name << " primitive " << i;
        const DepthRange full = pieceDepthRange(prim, w, Minv, W, H);
        const DepthRange reused = pieceDepthRange(prim, w, Minv, W, H, &ext);
        ASSERT_EQ(full.lo, reused.lo) << name << " primitive " << i << " at " << W << "x" << H;
        ASSERT_EQ(full.hi, reused.hi) << name << " primitive " << i << " at " << W << "x" << H;
        checked += full.lo <= full.hi;
        planar += prim.isPlanar() && !prim.solid;
        solid += prim.solid;
      }
    }
  }
  EXPECT_GT(checked, 5000);
  EXPECT_GT(planar, 0);
  EXPECT_GT(solid, 0);
}

// The world boxes the loader records (knownWorldBox) only leave out candidates that could
// not count: every primitive's screen box, x-y extent and depth range are those it has with
// the record removed, bit for bit, on the shipped scenes seen whole, zoomed in (pieces
// across the screen's edges), from close by (across the near plane), with the far plane
// through the scene, and orthographic; the faces left out are most of them, and some but
// not all of them for pieces across an edge, the near or the far plane.
TEST(WindowPrimitive, KnownWorldBoxesLeaveOutOnlyCandidatesThatCannotCount) {
  long long recorded = 0, skipped = 0, partial = 0, compared = 0, nearReached = 0, farReached = 0;
  for (const char* name : {"sphereflake", "molecule", "gallery", "cylinders", "vase_g0", "character", "quartic",
                           "macropatch_g1", "csg/csg_mechanical"}) {
    const Scene scene = loadScene(std::string(QACC_SOURCE_DIR) + "/scenes/" + name + ".json");
    Camera zoomed = scene.camera;
    zoomed.fov_y_deg /= 4;
    Camera close = scene.camera;
    close.eye = scene.camera.target + 0.3 * (scene.camera.eye - scene.camera.target);
    const double distance = (scene.camera.eye - scene.camera.target).norm();
    Camera cut = scene.camera;
    cut.far = distance;  // through the middle of the scene
    Camera ortho = scene.camera;
    ortho.type = Camera::Type::Orthographic;
    ortho.height = 2 * distance * std::tan(scene.camera.fov_y_deg * M_PI / 360);
    for (const Camera& cam : {scene.camera, zoomed, close, cut, ortho})
      for (const auto& [W, H] : {std::pair{160, 120}, std::pair{1920, 1080}}) {
        const Eigen::Matrix4d M = cam.worldToWindow(W, H), Minv = M.inverse();
        for (std::size_t i = 0; i < scene.primitives.size(); i += name == std::string("molecule") ? 3 : 1) {
          const Primitive& prim = scene.primitives[i];
          Primitive bare = prim;
          bare.known_box = {};
          ASSERT_EQ(unreachableViewFaces(bare, M, W, H), 0u);
          recorded += knownWorldBox(prim) != nullptr;
          Eigen::AlignedBox3d ext, bareExt;
          const WindowPrimitive w = toWindow(prim, int(i), M, Minv, W, H, &ext);
          const WindowPrimitive b = toWindow(bare, int(i), M, Minv, W, H, &bareExt);
          const std::string at = std::string(name) + " primitive " + std::to_string(i) + " at " + std::to_string(W);
          ASSERT_EQ(b.unreachable_view_faces, 0u) << at;
          skipped += __builtin_popcount(w.unreachable_view_faces);
          partial += w.unreachable_view_faces != 0 && w.unreachable_view_faces != 63;
          if (w.unreachable_view_faces != 0) {
            nearReached += (w.unreachable_view_faces & 16u) == 0;
            farReached += (w.unreachable_view_faces & 32u) == 0;
          }
          ASSERT_EQ(w.box.x0, b.box.x0) << at;
          ASSERT_EQ(w.box.y0, b.box.y0) << at;
          ASSERT_EQ(w.box.x1, b.box.x1) << at;
          ASSERT_EQ(w.box.y1, b.box.y1) << at;
          ASSERT_EQ(ext.isEmpty(), bareExt.isEmpty()) << at;
          if (!ext.isEmpty()) {
            ASSERT_EQ(ext.min(), bareExt.min()) << at;
            ASSERT_EQ(ext.max(), bareExt.max()) << at;
          }
          const DepthRange d = pieceDepthRange(prim, w, Minv, W, H), bd = pieceDepthRange(bare, b, Minv, W, H);
          ASSERT_EQ(d.lo, bd.lo) << at;
          ASSERT_EQ(d.hi, bd.hi) << at;
          const DepthRange dx = pieceDepthRange(prim, w, Minv, W, H, &ext);
          ASSERT_EQ(dx.lo, bd.lo) << at;
          ASSERT_EQ(dx.hi, bd.hi) << at;
          ++compared;
        }
      }
  }
  EXPECT_GT(compared, 20000);
  EXPECT_EQ(recorded, compared);  // the loader records every piece of these scenes
  EXPECT_GT(skipped, 3 * compared);
  EXPECT_GT(partial, 100);
  EXPECT_GT(nearReached, 10);
  EXPECT_GT(farReached, 10);
}

// A record is the loader's finding for the primitive as it was: a primitive changed after
// it (its quadric, a clip plane, solid), or moved, has none, and is set up in full.
TEST(WindowPrimitive, AWorldBoxRecordHoldsOnlyForThePrimitiveItWasFoundFor) {
  const Scene scene = loadScene(std::string(QACC_SOURCE_DIR) + "/scenes/molecule.json");
  const int W = 640, H = 360;
  const Eigen::Matrix4d M = scene.camera.worldToWindow(W, H);
  for (const Primitive& p : scene.primitives) ASSERT_NE(knownWorldBox(p), nullptr);
  const auto withClip = std::find_if(scene.primitives.begin(), scene.primitives.end(),
                                     [&](const Primitive& p) { return !p.clip.empty() && unreachableViewFaces(p, M, W, H) == 63u; });
  ASSERT_NE(withClip, scene.primitives.end());
  Primitive grown = *withClip;
  grown.quadric.Q(3, 3) -= 1e6;  // a far wider piece, across the whole view
  EXPECT_EQ(knownWorldBox(grown), nullptr);
  EXPECT_EQ(unreachableViewFaces(grown, M, W, H), 0u);
  Primitive reclipped = *withClip;
  reclipped.clip[0].p[3] += 1;
  EXPECT_EQ(knownWorldBox(reclipped), nullptr);
  Primitive flipped = *withClip;
  flipped.clip[0].owns_boundary = !flipped.clip[0].owns_boundary;
  EXPECT_EQ(knownWorldBox(flipped), nullptr);
  Primitive solid = *withClip;
  solid.solid = !solid.solid;
  EXPECT_EQ(knownWorldBox(solid), nullptr);
  Eigen::Matrix4d shift = Eigen::Matrix4d::Identity();
  shift(0, 3) = 1;
  EXPECT_EQ(knownWorldBox(withClip->transformed(shift)), nullptr);
  EXPECT_NE(knownWorldBox(Primitive(*withClip)), nullptr);  // a copy keeps it
}
