// CSG tile pruning (HwConfig::csg_tile_pruning, modeling/csg/csg_tree_pruning.h) in the
// accelerator: the images are the same with it on and off, in hw and in hw-cycle, on the
// shipped CSG scenes and on a scene where it drops leaves, products and whole tile jobs;
// hw and hw-cycle stay bit-identical with it on; the box tests are counted and timed.
#include <gtest/gtest.h>

#include <string>

#include "hw_model/engines/cycle_engine.h"
#include "hw_model/engines/functional_engine.h"
#include "hw_model/report/cost_model.h"
#include "modeling/loader/scene_loader.h"
#include "tests/hw_model/csg_scene_file.h"
#include "tests/hw_model/frame_expectations.h"

using namespace qacc;

namespace {

// One csg object: (A ∩ B) ∪ (C − D) ∪ (E − F). A and B overlap only in part, so the
// tiles of A alone skip the intersection and A with it; D sticks out of C's box, so the
// tiles of D alone skip the difference and D; the tiles between the parts, inside the
// union's box, hold no needed leaf.
Scene prunableScene() {
  return parseScene(R"({"format": "qacc-scene/1", "image": {"width": 320, "height": 240},
    "camera": {"eye": [0, -12, 0], "target": [0, 0, 0], "up": [0, 0, 1], "fov_y_deg": 40, "near": 4, "far": 30},
    "objects": [{"type": "csg", "op": "union", "children": [
      {"type": "csg", "op": "intersection", "children": [
        {"type": "sphere", "center": [-2.2, 0, 1.5], "radius": 1.5, "solid": true},
        {"type": "sphere", "center": [-0.8, 0, 1.5], "radius": 1.5, "solid": true}]},
      {"type": "csg", "op": "difference", "children": [
        {"type": "sphere", "center": [2, 0, 1.5], "radius": 1, "solid": true},
        {"type": "sphere", "center": [2.8, 0, 1.5], "radius": 0.9, "solid": true}]},
      {"type": "csg", "op": "difference", "children": [
        {"type": "cylinder", "base": [0, 0, -3], "top": [0, 0, -1], "radius": 1.2, "solid": true},
        {"type": "sphere", "center": [0, 0, -2], "radius": 0.5, "solid": true}]}]}]})",
                    "prunable.json", ".");
}

HwConfig pruning(bool on) {
  HwConfig c;
  c.csg_tile_pruning = on;
  return c;
}

// hw and hw-cycle with pruning on and off: four identical frames; returns the four runs.
struct Runs {
  HwRender hwOn, hwOff, cycleOn, cycleOff;
};
Runs runAll(const Scene& s, const std::string& name) {
  Runs r{renderHw(s, pruning(true), 2), renderHw(s, pruning(false), 2), renderHwCycle(s, pruning(true), 2),
         renderHwCycle(s, pruning(false), 2)};
  expectIdentical(r.hwOn.fb, r.hwOff.fb, name + ": hw, pruning on against off");
  expectIdentical(r.cycleOn.fb, r.cycleOff.fb, name + ": hw-cycle, pruning on against off");
  expectIdentical(r.hwOn.fb, r.cycleOn.fb, name + ": pruning on, hw against hw-cycle");
  EXPECT_EQ(r.hwOn.stats.csg.leaf_pixels, r.cycleOn.stats.csg.leaf_pixels) << name;
  EXPECT_EQ(r.hwOn.stats.csg.leaves_pruned, r.cycleOn.stats.csg.leaves_pruned) << name;
  EXPECT_EQ(r.hwOn.stats.csg.jobs_pruned, r.cycleOn.stats.csg.jobs_pruned) << name;
  // Off, nothing is tested or pruned; on, every job tests every leaf, and no leaf runs
  // that would not have run without pruning.
  EXPECT_EQ(r.hwOff.stats.csg.leaves_tested, 0u) << name;
  EXPECT_EQ(r.cycleOff.stats.csg.leaves_pruned + r.cycleOff.stats.csg.jobs_pruned, 0u) << name;
  EXPECT_GT(r.hwOn.stats.csg.leaves_tested, 0u) << name;
  EXPECT_LE(r.hwOn.stats.csg.leaf_pixels, r.hwOff.stats.csg.leaf_pixels) << name;
  return r;
}

}  // namespace

TEST(CsgTilePruning, ShippedScenesAreTheSameWithPruningOnAndOff) {
  for (const char* name : {"csg_mechanical", "csg_quadrics", "csg_molecule"}) runAll(csgScene(name, 240, 180), name);
}

TEST(CsgTilePruning, APrunableSceneDropsLeavesAndJobsAndKeepsItsImage) {
  const Runs r = runAll(prunableScene(), "prunable");
  const CsgCounters& on = r.cycleOn.stats.csg;
  const CsgCounters& off = r.cycleOff.stats.csg;
  EXPECT_GT(on.leaves_pruned, 0u);
  EXPECT_GT(on.products_pruned, 0u);
  EXPECT_GT(on.jobs_pruned, 0u);
  EXPECT_LT(on.leaf_pixels, off.leaf_pixels);  // the pruned leaves' pixels are not evaluated
  EXPECT_GT(r.hwOn.stats.pixels.written, 1000u);
  // The box tester works serially: at least one cycle per leaf tested.
  EXPECT_GT(on.cycles, 0u);
  EXPECT_GE(on.cycles, on.leaves_tested);
  // Every unit accounts for every cycle of the frame.
  for (const UnitStats& u : r.cycleOn.stats.units)
    EXPECT_EQ(u.busy + u.stall + u.idle, r.cycleOn.stats.cycles) << u.name;
}

TEST(CsgTilePruning, TheBoxTesterIsPricedOnlyWhenOn) {
  const CostModel on = CostModel::of(pruning(true)), off = CostModel::of(pruning(false));
  EXPECT_GT(on.csgGe(), off.csgGe());
  EXPECT_GT(on.csgPruneFlagBits, 0.0);
  EXPECT_EQ(off.csgPruneFlagBits, 0.0);
  bool found = false;
  for (const UnitCost& u : on.csgUnits) found |= u.unit == "csg_box_tester";
  EXPECT_TRUE(found);
}

TEST(CsgTilePruning, TheShippedConfigTurnsItOff) {
  const HwConfig c = loadHwConfig(std::string(QACC_SOURCE_DIR) + "/hw_model/configs/default_no_csg_pruning.json");
  EXPECT_FALSE(c.csg_tile_pruning);
  EXPECT_TRUE(HwConfig().csg_tile_pruning);
  EXPECT_THROW(parseHwConfig(R"({"format": "qacc-hw-config/1", "csg_tile_pruning": 1})", "x.json"),
               std::invalid_argument);
}
