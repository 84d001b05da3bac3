// Traversal spans (datapath/span_solver.h): every pixel the pixel datapath covers lies in a
// span of its row, spans are ordered and disjoint, at most two per row, and only a few
// pixels wider than the coverage they stand for.
#include <gtest/gtest.h>

#include "hw_model/datapath/pixel_datapath.h"
#include "hw_model/datapath/setup_arithmetic.h"
#include "hw_model/datapath/span_solver.h"
#include "modeling/geometry/natural_quadrics.h"
#include "modeling/scene/scene.h"

using namespace qacc;

namespace {

Scene sceneOf(const Primitive& p, const Eigen::Vector3d& eye) {
  Scene s;
  s.name = "span";
  s.width = 96;
  s.height = 80;
  s.camera.eye = eye;
  s.camera.target = {0, 0, 0};
  s.lights = Scene::defaultLights(s.camera);
  s.materials.emplace_back();
  s.primitives.push_back(p);
  s.objects.push_back({"p", 0, 1, 0, -1, {}});
  return s;
}

struct RowStats {
  int rows = 0, twoSpanRows = 0;
  long long covered = 0, issued = 0;
};

RowStats checkSpans(const Scene& scene) {
  const HwConfig cfg;
  OverflowCounter ovf;
  const Eigen::Matrix4d M = scene.camera.worldToWindow(scene.width, scene.height);
  const PrimitiveSetup s = setupPrimitive(scene, 0, M, M.inverse(), cfg, ovf);
  EXPECT_TRUE(s.visible);
  RowStats st;
  PixelDatapath dp(s, cfg);
  OverflowCounters oc;
  for (int y = s.y0; y < s.y1; ++y) {
    Span sp[2];
    const int n = solveSpans(s, y, s.x0, s.x1, sp);
    EXPECT_LE(n, 2);
    for (int k = 0; k < n; ++k) {
      EXPECT_LT(sp[k].x0, sp[k].x1) << "row " << y;
      EXPECT_GE(sp[k].x0, s.x0);
      EXPECT_LE(sp[k].x1, s.x1);
      st.issued += sp[k].x1 - sp[k].x0;
    }
    if (n == 2) {
      EXPECT_LT(sp[0].x1, sp[1].x0) << "row " << y << ": spans ordered and disjoint";
      ++st.twoSpanRows;
    }
    ++st.rows;
    // Coverage by the datapath, pixel by pixel over the whole box row.
    dp.startSpan(0, y - s.y0);
    for (int x = s.x0; x < s.x1; ++x) {
      const PixelOutcome o = dp.evaluate(oc);
      dp.stepRight();
      if (!o.candidate) continue;
      ++st.covered;
      bool inSpan = false;
      for (int k = 0; k < n; ++k) inSpan |= x >= sp[k].x0 && x < sp[k].x1;
      EXPECT_TRUE(inSpan) << "pixel (" << x << ", " << y << ") reaches the clip unit but lies in no span";
    }
  }
  return st;
}

}  // namespace

TEST(SpanSolver, SphereRowsCoverEveryCandidatePixelAndLittleMore) {
  const RowStats st = checkSpans(sceneOf(makeSphere({0, 0, 0}, 1.0), {0, 0, 4}));
  EXPECT_GT(st.covered, 1000);
  EXPECT_EQ(st.twoSpanRows, 0);
  // Widened by at most 1 + 2 pixels per span end against the quantisation of Δ.
  EXPECT_LE(st.issued, st.covered + 5LL * st.rows);
}

TEST(SpanSolver, HyperbolaRowsHaveTwoSpans) {
  // A hyperbolic cylinder seen along its axis: its contour is the two branches of a
  // hyperbola, so rows have a span on each side.
  const RowStats st = checkSpans(sceneOf(makeHyperbolicCylinder(0.5, 0.6, 1.5, 2.0), {0.01, 0.02, 6}));
  EXPECT_GT(st.covered, 500);
  EXPECT_GT(st.twoSpanRows, 0);
  EXPECT_LE(st.issued, st.covered + 10LL * st.rows);
}
