// Coincident faces through the accelerator's CSG path (hw_model/engines/csg_tile.h): the
// notched cube of CsgReference.CoincidentFacesLeaveNoSpeckles (three slab quadrics
// intersected, minus a box sharing three of the cube's faces), turned and seen in
// perspective, drawn by hw: no speckle (a pixel whose four neighbours agree on another
// primitive), no pinhole or spurious pixel against the reference, and the same image from
// hw-cycle. With ends within 4 depth LSBs as one event (kCsgEndTolerance, csg_tile.h) the
// second orientation kept a sliver of the cube at 4 pixels in the notch (2 speckles, 4
// spurious).
#include <gtest/gtest.h>

#include "hw_model/engines/cycle_engine.h"
#include "hw_model/engines/functional_engine.h"
#include "hw_model/report/accuracy_report.h"
#include "modeling/loader/scene_loader.h"
#include "raster/reference/reference_renderer.h"
#include "tests/raster/notched_cube_scene.h"

using namespace qacc;

TEST(CsgEngine, CoincidentFacesLeaveNoSpecklesInHw) {
  for (const char* angles : {"[20, 35, 10]", "[-30, 15, 50]", "[45, 45, 0]"}) {
    const Scene s = parseScene(notchedCubeScene(angles), "t.json", ".");
    const HwConfig cfg;
    const HwRender hw = renderHw(s, cfg, 2);
    const FrameBuffer& fb = hw.fb;
    EXPECT_EQ(countSpeckles(fb), 0) << angles;
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
