// The accelerator's CSG path (hw_model/engines/csg_tile.h) on the shipped CSG scenes:
// against the reference within the accuracy of the non-CSG scenes (<= 0.1 % wrong pixels,
// no pinholes), the same image for 1 and 3 threads and from hw-cycle.
#include <gtest/gtest.h>

#include <string>

#include "hw_model/engines/cycle_engine.h"
#include "hw_model/engines/functional_engine.h"
#include "hw_model/report/accuracy_report.h"
#include "modeling/loader/scene_loader.h"
#include "modeling/scene/scene_error.h"
#include "raster/reference/reference_renderer.h"
#include "tests/hw_model/csg_scene_file.h"

using namespace qacc;

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
    EXPECT_EQ(a.stats.pixels.written, b.stats.pixels.written) << name;
    EXPECT_EQ(a.stats.csg.overflowed_pixels, 0u) << name;  // the default depth holds every shipped scene
  }
}

// The CSG pass of hw-cycle is simulated: its cycles come from the timed units and are
// bounded below by the work of its slowest stage (each pipeline issues, inserts and sweeps
// at most one pixel, interval or list end per cycle).
TEST(CsgEngine, HwCycleSimulatesTheCsgPass) {
  for (const char* name : {"csg_mechanical", "csg_quadrics"}) {
    const Scene s = csgScene(name, 240, 180);
    HwConfig one, two;
    one.pipelines = 1;
    two.pipelines = 2;
    const HwRender a = renderHwCycle(s, one, 2), b = renderHwCycle(s, two, 2);
    EXPECT_EQ(a.fb.color.data, b.fb.color.data) << name;
    for (const HwRender* r : {&a, &b}) {
      const CsgCounters& c = r->stats.csg;
      const std::uint64_t P = std::uint64_t(r->stats.configuration.pipelines);
      EXPECT_GT(c.cycles, 0u) << name;
      EXPECT_GE(r->stats.cycles, c.cycles) << name;
      EXPECT_GE(c.cycles * P, c.leaf_pixels) << name;
      EXPECT_GE(c.cycles * P, c.interval_ends) << name;
      // Every unit accounts for every cycle of the frame.
      for (const UnitStats& u : r->stats.units)
        EXPECT_EQ(u.busy + u.stall + u.idle, r->stats.cycles) << name << " " << u.name;
    }
    EXPECT_GT(a.stats.csg.cycles, b.stats.csg.cycles) << name;  // one pipeline is slower
  }
}

// A list depth below the scene's need overflows: the pixels are counted, the nearest
// intervals kept, every pixel that differs from the unbounded image is among the counted
// ones, and hw-cycle still draws the same image.
TEST(CsgEngine, ASmallListDepthOverflowsVisibly) {
  const Scene s = csgScene("csg_mechanical", 240, 180);
  HwConfig small;
  small.csg_list_depth = 2;
  const HwRender full = renderHw(s, HwConfig(), 2), a = renderHw(s, small, 2), b = renderHwCycle(s, small, 2);
  EXPECT_EQ(full.stats.csg.overflowed_pixels, 0u);
  EXPECT_GT(a.stats.csg.overflowed_pixels, 0u);
  EXPECT_GT(a.stats.csg.dropped_intervals, 0u);
  EXPECT_LT(a.stats.csg.interval_ends, full.stats.csg.interval_ends);
  EXPECT_EQ(a.stats.csg.max_list_ends, full.stats.csg.max_list_ends);  // the demand, before bounding
  std::uint64_t differing = 0;
  for (std::size_t i = 0; i < a.fb.primitive.size(); ++i)
    differing += a.fb.primitive[i] != full.fb.primitive[i] || a.fb.depth[i] != full.fb.depth[i];
  EXPECT_LE(differing, a.stats.csg.overflowed_pixels);
  EXPECT_EQ(a.fb.color.data, b.fb.color.data);
  EXPECT_EQ(a.fb.primitive, b.fb.primitive);
  EXPECT_EQ(a.stats.csg.overflowed_pixels, b.stats.csg.overflowed_pixels);
}

// A csg object with more leaves than the list entries can name is refused with its path.
TEST(CsgEngine, RefusesATreeTheListsCannotAddress) {
  const Scene s = csgScene("csg_mechanical", 120, 90);
  HwConfig narrow;
  narrow.csg_leaf_bits = 2;
  try {
    renderHw(s, narrow, 1);
    FAIL() << "accepted";
  } catch (const SceneError& e) {
    EXPECT_NE(std::string(e.what()).find("/objects/"), std::string::npos) << e.what();
    EXPECT_NE(std::string(e.what()).find("csg_leaf_bits"), std::string::npos) << e.what();
  }
}
