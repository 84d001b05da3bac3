// Units a scene does not use cost it no host time (issue 13, deliverable 4): without csg
// objects the CSG frame makes no per-primitive window forms or tree indices (the hw and
// hw-cycle engines build one per frame), with them it does.
#include <gtest/gtest.h>

#include <string>

#include "hw_model/config/hw_config.h"
#include "hw_model/engines/csg_tile.h"
#include "modeling/loader/scene_loader.h"

using namespace qacc;

TEST(UnusedUnits, ACsgFrameOfASceneWithoutCsgObjectsHoldsNothing) {
  const Scene spheres = loadScene(std::string(QACC_SOURCE_DIR) + "/scenes/sphereflake.json");
  ASSERT_GT(spheres.primitives.size(), 100u);
  const HwConfig cfg;
  const CsgFrame none(spheres, cfg, spheres.width, spheres.height);
  EXPECT_TRUE(none.trees.empty());
  EXPECT_TRUE(none.win.empty());
  EXPECT_TRUE(none.treeOfPrimitive.empty());
  EXPECT_EQ(none.treeOf(0), -1);
  EXPECT_EQ(none.treeOf(spheres.primitives.size() - 1), -1);

  const Scene csg = loadScene(std::string(QACC_SOURCE_DIR) + "/scenes/csg/csg_quadrics.json");
  const CsgFrame some(csg, cfg, csg.width, csg.height);
  ASSERT_FALSE(some.trees.empty());
  EXPECT_EQ(some.win.size(), csg.primitives.size());
  int leaves = 0;
  for (std::size_t i = 0; i < csg.primitives.size(); ++i) leaves += some.treeOf(i) >= 0;
  EXPECT_GT(leaves, 0);
}
