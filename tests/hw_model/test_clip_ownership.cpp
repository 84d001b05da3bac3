// Boundary ownership through the accelerator (issue 14): two cells sharing a clip plane — one
// with the plane, the other with its opposite — must keep complementary sets of pixel
// centres. hw used to quantise each plane on the primitive's own box (origin at the box
// corner, block exponent from the box), so the two cells rounded the shared plane
// differently and, where the plane passes through pixel centres, both dropped a whole
// column (x = -2.5 / 64 below: 102 pinholes at 160x120 with the default configuration; the
// minimal and wide ones gave the column to the cell the reference does not, 102
// wrong-object pixels, as the window planes were divided by their largest coefficient,
// which rounds).
#include <gtest/gtest.h>

#include <sstream>

#include "hw_model/datapath/setup_arithmetic.h"
#include "hw_model/engines/cycle_engine.h"
#include "hw_model/engines/functional_engine.h"
#include "hw_model/report/accuracy_report.h"
#include "modeling/geometry/natural_quadrics.h"
#include "raster/reference/reference_renderer.h"

using namespace qacc;

namespace {

// Two cells of one sphere split by `plane`: the first keeps p·X <= 0, the second the opposite.
Scene splitSphere(const Camera& cam, const HalfSpace& plane, double radius, bool solid, bool both = true,
                  int which = 0) {
  Scene s;
  s.name = "split";
  s.width = 160;
  s.height = 120;
  s.camera = cam;
  s.lights = Scene::defaultLights(cam);
  s.materials.emplace_back();
  const HalfSpace sides[2] = {plane, plane.opposite()};
  for (int i = 0; i < 2; ++i) {
    if (!both && i != which) continue;
    Primitive p = makeSphere({0, 0, 0}, radius);
    p.solid = solid;
    p.clip.push_back(sides[i]);
    p.object = int(s.objects.size());
    s.primitives.push_back(p);
    s.objects.push_back({"sphere", s.primitives.size() - 1, 1, 0, -1, {}});
  }
  return s;
}

Camera orthographic() {
  Camera c;
  c.type = Camera::Type::Orthographic;
  c.height = 1.875;  // 64 pixels per world unit at 120 rows: x = (k + 0.5) / 64 is a column of pixel centres
  return c;
}

// hw (default configuration) keeps each pixel centre of the shared plane in exactly one cell:
// no pixel drawn by both cells alone, no pinhole against the reference with both; hw-cycle
// identical.
void checkOwnership(const Camera& cam, const HalfSpace& plane, double radius, bool solid, const std::string& what,
                    bool sameTieAsReference) {
  const HwConfig cfg;
  const Scene both = splitSphere(cam, plane, radius, solid);
  const HwRender a = renderHw(splitSphere(cam, plane, radius, solid, false, 0), cfg, 2);
  const HwRender b = renderHw(splitSphere(cam, plane, radius, solid, false, 1), cfg, 2);
  std::size_t twice = 0;
  for (std::size_t i = 0; i < a.fb.object.size(); ++i) twice += a.fb.object[i] >= 0 && b.fb.object[i] >= 0;
  EXPECT_EQ(twice, 0u) << what << ": pixel centres kept by both cells";
  const HwRender hw = renderHw(both, cfg, 2);
  const AccuracyReport r = accuracyReport(renderReference(both, 2), hw.fb, cam);
  EXPECT_GT(r.reference_covered, 1000u) << what;
  EXPECT_EQ(r.pinholes, 0u) << what << ": " << r.line();
  if (sameTieAsReference) {
    EXPECT_EQ(r.wrong_object, 0u) << what << ": " << r.line();
  }
  const HwRender c = renderHwCycle(both, cfg, 1);
  EXPECT_TRUE(c.fb.object == hw.fb.object) << what << ": hw-cycle differs";
}

}  // namespace

// Planes x = (k + 0.5) / 64 seen orthographically: every pixel centre of a column lies on the
// plane exactly, so the reference's tie (ownership) and hw's agree as well.
TEST(ClipOwnership, SharedPlaneThroughAColumnOfPixelCentresOrthographic) {
  for (bool solid : {false, true})
    for (int k = -3; k <= 3; ++k) {
      const HalfSpace plane(Eigen::Vector4d(1, 0, 0, -(k + 0.5) / 64));
      checkOwnership(orthographic(), plane, 0.8, solid,
                     "x = " + std::to_string(k) + ".5 / 64" + (solid ? " solid" : ""), true);
    }
}

// Planes through the eye and a column (or a row) of pixel centres, in perspective: the
// window-space plane x = X + 0.5 carried to world space (p = Mᵀ p'). The centres lie on it
// to rounding only, so which cell owns them may differ from the reference's choice, but one
// and only one does.
TEST(ClipOwnership, SharedPlaneThroughTheEyeAndPixelCentresPerspective) {
  Camera cam;
  cam.eye = {0.3, 0.2, 5};
  const Eigen::Matrix4d M = cam.worldToWindow(160, 120);
  for (bool solid : {false, true})
    for (const Eigen::Vector4d& pw : {Eigen::Vector4d(1, 0, 0, -80.5), Eigen::Vector4d(1, 0, 0, -63.5),
                                      Eigen::Vector4d(0, 1, 0, -59.5), Eigen::Vector4d(1, 1, 0, -140)}) {
      const HalfSpace plane(Eigen::Vector4d(M.transpose() * pw));
      std::ostringstream what;
      what << "window plane " << pw.transpose() << (solid ? " solid" : "");
      checkOwnership(cam, plane, 1.0, solid, what.str(), false);
    }
}

// The setup arithmetic itself: at every pixel of both boxes, the plane values of the two
// cells are exact integer negations, whatever their boxes.
TEST(ClipOwnership, OppositePlanesQuantiseToExactNegations) {
  Camera cam;
  cam.eye = {0.7, -0.4, 4};
  const Eigen::Matrix4d M = cam.worldToWindow(160, 120), Minv = M.inverse();
  const HwConfig cfg;
  for (const Eigen::Vector4d& p : {Eigen::Vector4d(1, 0.3, 0.1, -0.05), Eigen::Vector4d(-0.2, 1, 0.7, 0.3),
                                   Eigen::Vector4d(0.01, 0.02, 1, 0.1)}) {
    const Scene s = splitSphere(cam, HalfSpace(p), 1.0, false);
    OverflowCounter ovf;
    const PrimitiveSetup a = setupPrimitive(s, 0, M, Minv, cfg, ovf), b = setupPrimitive(s, 1, M, Minv, cfg, ovf);
    ASSERT_TRUE(a.x1 > a.x0 && b.x1 > b.x0);
    ASSERT_EQ(a.planes.size(), 1u);
    ASSERT_EQ(b.planes.size(), 1u);
    const PlaneSetup &pa = a.planes[0], &pb = b.planes[0];
    EXPECT_EQ(pa.pz, -pb.pz);
    EXPECT_NE(pa.owns, pb.owns);
    for (int y = std::min(a.y0, b.y0); y < std::max(a.y1, b.y1); ++y)
      for (int x = std::min(a.x0, b.x0); x < std::max(a.x1, b.x1); ++x) {
        const i128 ha = pa.h.A * (x - a.x0) + pa.h.B * (y - a.y0) + pa.h.C;
        const i128 hb = pb.h.A * (x - b.x0) + pb.h.B * (y - b.y0) + pb.h.C;
        ASSERT_TRUE(ha == -hb) << "pixel " << x << "," << y << " of plane " << p.transpose();
      }
  }
}
