// Coincident faces through the accelerator's CSG path (hw_model/engines/csg_tile.h): the
// notched cube of CsgReference.CoincidentFacesLeaveNoSpeckles (three slab quadrics
// intersected, minus a box sharing three of the cube's faces), turned and seen in
// perspective, drawn by hw: no speckle (a pixel whose four neighbours agree on another
// primitive), no pinhole or spurious pixel against the reference, and the same image from
// hw-cycle. With ends within 4 depth LSBs as one event (kCsgEndTolerance, csg_tile.h) the
// second orientation kept a sliver of the cube at 4 pixels in the notch (2 speckles, 4
// spurious).
#include <gtest/gtest.h>

#include <string>

#include "hw_model/engines/cycle_engine.h"
#include "hw_model/engines/functional_engine.h"
#include "hw_model/report/accuracy_report.h"
#include "modeling/loader/scene_loader.h"
#include "raster/reference/reference_renderer.h"

using namespace qacc;

TEST(CsgEngine, CoincidentFacesLeaveNoSpecklesInHw) {
  for (const char* angles : {"[20, 35, 10]", "[-30, 15, 50]", "[45, 45, 0]"}) {
    const std::string scene = R"({"format": "qacc-scene/1", "image": {"width": 240, "height": 240},
      "camera": {"eye": [2.5, 3.1, 3.7], "target": [0, 0, 0], "fov_y_deg": 45, "near": 0.5, "far": 20},
      "objects": [{"type": "csg", "op": "difference", "transform": {"rotate_deg": )" + std::string(angles) + R"(},
        "children": [
          {"type": "csg", "op": "intersection", "children": [
            {"type": "quadric", "matrix": [[1,0,0,0],[0,0,0,0],[0,0,0,0],[0,0,0,-1]], "solid": true},
            {"type": "quadric", "matrix": [[0,0,0,0],[0,1,0,0],[0,0,0,0],[0,0,0,-1]], "solid": true},
            {"type": "quadric", "matrix": [[0,0,0,0],[0,0,0,0],[0,0,1,0],[0,0,0,-1]], "solid": true}]},
          {"type": "plane", "point": [0, 0, 1], "normal": [0, 0, 1], "solid": true,
           "clip": [[1,0,0,-1],[-1,0,0,0],[0,1,0,-1],[0,-1,0,0],[0,0,-1,0]]}]}]})";
    const Scene s = parseScene(scene, "t.json", ".");
    const HwConfig cfg;
    const HwRender hw = renderHw(s, cfg, 2);
    const FrameBuffer& fb = hw.fb;
    const int N = 240;
    int speckles = 0;
    for (int y = 1; y + 1 < N; ++y)
      for (int x = 1; x + 1 < N; ++x) {
        auto at = [&](int u, int v) { return fb.primitive[std::size_t(v) * N + std::size_t(u)]; };
        const int n = at(x - 1, y);
        if (at(x + 1, y) == n && at(x, y - 1) == n && at(x, y + 1) == n && at(x, y) != n) ++speckles;
      }
    EXPECT_EQ(speckles, 0) << angles;
    EXPECT_GT(fb.covered(), 5000u);
    const AccuracyReport a = accuracyReport(renderReference(s, 2), fb, s.camera);
    EXPECT_EQ(a.pinholes, 0u) << angles << ": " << a.line();
    EXPECT_EQ(a.spurious, 0u) << angles << ": " << a.line();
    EXPECT_EQ(a.wrong_fraction, 0.0) << angles << ": " << a.line();
    const HwRender cyc = renderHwCycle(s, cfg, 2);
    EXPECT_EQ(cyc.fb.primitive, fb.primitive) << angles;
    EXPECT_EQ(cyc.fb.color.data, fb.color.data) << angles;
  }
}
