// The accelerator's CSG path (hw_model/engines/csg_tile.h) on the shipped CSG scenes:
// against the reference within the accuracy of the non-CSG scenes (<= 0.1 % wrong pixels,
// no pinholes), the same image for 1 and 3 threads and from hw-cycle.
#include <gtest/gtest.h>

#include <string>

#include "hw_model/engines/cycle_engine.h"
#include "hw_model/engines/functional_engine.h"
#include "hw_model/report/accuracy_report.h"
#include "modeling/loader/scene_loader.h"
#include "raster/reference/reference_renderer.h"

using namespace qacc;

namespace {

Scene csgScene(const std::string& name, int w, int h) {
  Scene s = loadScene(std::string(QACC_SOURCE_DIR) + "/scenes/csg/" + name + ".json");
  s.width = w;
  s.height = h;
  return s;
}

}  // namespace

TEST(CsgEngine, HwMatchesTheReferenceOnEveryCsgScene) {
  const HwConfig cfg;
  for (const char* name : {"csg_mechanical", "csg_quadrics", "csg_molecule"}) {
    const Scene s = csgScene(name, 480, 360);
    const FrameBuffer ref = renderReference(s, 2);
    const HwRender hw = renderHw(s, cfg, 2);
    const AccuracyReport a = accuracyReport(ref, hw.fb, s.camera);
    EXPECT_GT(a.reference_covered, 10000u) << name;
    EXPECT_LE(a.wrong_fraction, 0.001) << name << ": " << a.line();
    EXPECT_EQ(a.pinholes, 0u) << name << ": " << a.line();
    EXPECT_LE(double(a.spurious), 0.001 * double(a.reference_covered)) << name << ": " << a.line();
    EXPECT_GT(hw.stats.csg.resolved, 0u);
    EXPECT_GE(hw.stats.csg.max_list_ends, 2u);
  }
}

TEST(CsgEngine, ThreadCountDoesNotChangeTheHwImage) {
  const HwConfig cfg;
  const Scene s = csgScene("csg_quadrics", 320, 240);
  const HwRender a = renderHw(s, cfg, 1), b = renderHw(s, cfg, 3);
  EXPECT_EQ(a.fb.color.data, b.fb.color.data);
  EXPECT_EQ(a.fb.depth, b.fb.depth);
  EXPECT_EQ(a.fb.primitive, b.fb.primitive);
}

TEST(CsgEngine, HwCycleIsBitIdenticalToHwOnCsgScenes) {
  const HwConfig cfg;
  for (const char* name : {"csg_mechanical", "csg_quadrics", "csg_molecule"}) {
    const Scene s = csgScene(name, 240, 180);
    const HwRender a = renderHw(s, cfg, 2), b = renderHwCycle(s, cfg, 2);
    EXPECT_EQ(a.fb.color.data, b.fb.color.data) << name;
    EXPECT_EQ(a.fb.depth, b.fb.depth) << name;
    EXPECT_EQ(a.fb.primitive, b.fb.primitive) << name;
    EXPECT_EQ(a.stats.csg.interval_ends, b.stats.csg.interval_ends) << name;
    EXPECT_GT(b.stats.csg.estimated_cycles, 0u) << name;
    EXPECT_GE(b.stats.cycles, b.stats.csg.estimated_cycles) << name;
  }
}
