// Degenerate and extreme cases through the accelerator (issue 3): each renders without
// hanging, with integer datapaths (no NaN possible), and within a stated error of the
// reference: at most 0.1 % of the reference's covered pixels wrong or missing, at most
// 0.1 % spurious, PSNR above 30 dB; hw-cycle bit-identical to hw.
#include <gtest/gtest.h>

#include "hw_model/report/accuracy_report.h"
#include "hw_model/engines/cycle_engine.h"
#include "hw_model/engines/functional_engine.h"
#include "hw_model/datapath/setup_arithmetic.h"
#include "modeling/geometry/natural_quadrics.h"
#include "raster/reference/reference_renderer.h"

using namespace qacc;

namespace {

Scene makeScene(int w, int h, const Camera& cam, const std::vector<Primitive>& prims) {
  Scene s;
  s.name = "extreme";
  s.width = w;
  s.height = h;
  s.camera = cam;
  s.lights = Scene::defaultLights(cam);
  s.materials.emplace_back();
  for (std::size_t i = 0; i < prims.size(); ++i) {
    Primitive p = prims[i];
    p.object = int(i);
    p.material = 0;
    s.primitives.push_back(p);
    s.objects.push_back({"quadric", i, 1, 0, -1, {}});
  }
  return s;
}

AccuracyReport check(const Scene& scene, bool cycleToo, const std::string& what) {
  const FrameBuffer ref = renderReference(scene, 2);
  const HwRender hw = renderHw(scene, HwConfig(), 2);
  const AccuracyReport a = accuracyReport(ref, hw.fb, scene.camera);
  EXPECT_GT(a.reference_covered, 0u) << what;
  EXPECT_LE(a.wrong_fraction, 1e-3) << what << ": " << a.line();
  EXPECT_LE(double(a.spurious), 1e-3 * double(a.reference_covered) + 2) << what << ": " << a.line();
  EXPECT_GT(a.psnr_db, 30.0) << what << ": " << a.line();
  std::size_t nans = 0;
  for (double d : hw.fb.depth) nans += std::isnan(d);
  EXPECT_EQ(nans, 0u) << what;
  if (cycleToo) {
    const HwRender c = renderHwCycle(scene, HwConfig(), 1);
    EXPECT_TRUE(c.fb.color.data == hw.fb.color.data && c.fb.object == hw.fb.object) << what << ": hw-cycle differs";
  }
  return a;
}

Camera perspective(const Eigen::Vector3d& eye, const Eigen::Vector3d& target, double nearP = 0.1, double farP = 100) {
  Camera c;
  c.eye = eye;
  c.target = target;
  c.up = {0, 1, 0};
  c.near = nearP;
  c.far = farP;
  return c;
}

}  // namespace

TEST(HwExtremes, ParaboloidSeenAlongItsAxisHasAZero) {
  Camera c;
  c.type = Camera::Type::Orthographic;
  c.eye = {0, 0, 5};
  c.target = {0, 0, 0};
  c.height = 3;
  for (bool solid : {false, true}) {
    Primitive p = makeParaboloid(1.0, 1.0, 2.0);
    p.solid = solid;
    const Scene s = makeScene(200, 200, c, {p});
    OverflowCounter ovf;
    const Eigen::Matrix4d M = c.worldToWindow(200, 200);
    const PrimitiveSetup st = setupPrimitive(s, 0, M, M.inverse(), HwConfig(), ovf);
    EXPECT_EQ(st.a, 0) << "the case under test: a = 0 in window space";
    const AccuracyReport a = check(s, true, solid ? "solid paraboloid along axis" : "paraboloid along axis");
    EXPECT_EQ(a.pinholes, 0u);
  }
}

TEST(HwExtremes, GrazingSilhouettes) {
  // A long cylinder almost along the line of sight and a sphere seen at its rim.
  const Scene s = makeScene(240, 180, perspective({0.3, 0.2, 6}, {0, 0, 0}),
                            {makeCylinder({0, 0, -30}, {0, 0, 2}, 0.5), makeSphere({1.2, 0.4, -1}, 0.7)});
  check(s, true, "grazing");
}

TEST(HwExtremes, QuadricCrossingTheNearPlane) {
  Primitive solid = makeSphere({0, 0, 4.9}, 0.4);  // eye at z = 5, near 0.1: cut by the near plane
  solid.solid = true;
  const Scene s = makeScene(200, 150, perspective({0, 0, 5}, {0, 0, 0}),
                            {makeSphere({0.15, 0, 4.85}, 0.3), solid, makeSphere({0, 0, 0}, 1)});
  check(s, true, "near plane");
}

TEST(HwExtremes, SphereAroundTheEye) {
  const Scene s = makeScene(200, 150, perspective({0, 0, 0}, {0, 0, -1}), {makeSphere({0.5, 0.2, 0}, 5)});
  const AccuracyReport a = check(s, true, "sphere around the eye");
  EXPECT_EQ(a.reference_covered, 200u * 150u);  // the inside of the sphere fills the screen
  EXPECT_EQ(a.pinholes, 0u);
}

TEST(HwExtremes, Image4096x4096) {
  const Scene s = makeScene(4096, 4096, perspective({0, 0, 6}, {0, 0, 0}),
                            {makeSphere({0, 0, 0}, 1), makeCylinder({-1.5, -1, 0}, {-1.5, 1, 0.5}, 0.3)});
  const AccuracyReport a = check(s, false, "4096x4096");
  EXPECT_EQ(a.pinholes, 0u);
}

TEST(HwExtremes, ScaleRatioOfAMillion) {
  // A ground sphere of radius 1e4 under a sphere of radius 1e-2.
  const Scene s = makeScene(240, 180, perspective({0, 0.02, 0.12}, {0, 0, 0}, 0.01, 1e5),
                            {makeSphere({0, -1e4 - 0.011, 0}, 1e4), makeSphere({0, 0, 0}, 1e-2)});
  const AccuracyReport a = check(s, true, "scale ratio 1e6");
  EXPECT_EQ(a.pinholes, 0u);
}

// Issue 14: a specular weight above about 5e5 overflowed the 32-bit specular table (13 dB,
// said nowhere) and light colours of 256 and more were clamped silently. Now the table
// saturates and both are counted as shading overflows.
TEST(HwExtremes, ShadingFormatsOverflowsAreCounted) {
  Scene s = makeScene(120, 90, perspective({0, 0, 5}, {0, 0, 0}), {makeSphere({0, 0, 0}, 1.0)});
  s.materials[0].specular = 1e6;
  HwRender hw = renderHw(s, HwConfig(), 2);
  EXPECT_GT(hw.stats.overflow.shading.events, 0u);
  const FrameBuffer ref = renderReference(s, 2);
  const AccuracyReport r = accuracyReport(ref, hw.fb, s.camera);
  EXPECT_GT(r.psnr_db, 30.0) << r.line();
  s.materials[0].specular = 0.2;
  hw = renderHw(s, HwConfig(), 2);
  EXPECT_EQ(hw.stats.overflow.shading.events, 0u);
  s.lights[0].color = {300, 300, 300};
  hw = renderHw(s, HwConfig(), 2);
  EXPECT_GT(hw.stats.overflow.shading.events, 0u) << "a light colour above 256 was clamped silently";
}
