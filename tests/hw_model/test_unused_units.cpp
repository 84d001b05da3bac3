// Units a scene does not use cost it no host time (issue 13, deliverable 4): without csg
// objects the CSG frame makes no per-primitive window forms or tree indices (the hw and
// hw-cycle engines build one per frame), with them it does; a material no primitive uses
// gets no specular ROM.
#include <gtest/gtest.h>

#include <string>

#include "hw_model/config/hw_config.h"
#include "hw_model/datapath/shading_arithmetic.h"
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

TEST(UnusedUnits, AMaterialNoPrimitiveUsesGetsNoSpecularTable) {
  const std::string text = R"js({"format": "qacc-scene/1", "image": {"width": 64, "height": 48},
    "camera": {"type": "perspective", "eye": [0, 0, 10], "target": [0, 0, 0], "fov_y_deg": 30, "near": 1, "far": 50},
    "materials": {"used": {"color": [0.8, 0.2, 0.2], "specular": 0.5, "shininess": 32},
                  "unused": {"color": [0.2, 0.8, 0.2], "specular": 0.5, "shininess": 32}},
    "objects": [{"type": "sphere", "center": [0, 0, 0], "radius": 1, "material": "used"}]})js";
  const Scene s = parseScene(text, "s.json", ".");
  const HwConfig cfg;
  OverflowCounter ovf;
  const LightingSetup L = LightingSetup::build(s, cfg, ovf);
  ASSERT_EQ(L.materials.size(), s.materials.size());
  int used = -1, unused = -1;
  for (std::size_t k = 0; k < s.materials.size(); ++k) {
    if (s.materials[k].name == "used") used = int(k);
    if (s.materials[k].name == "unused") unused = int(k);
  }
  ASSERT_GE(used, 0);
  ASSERT_GE(unused, 0);
  ASSERT_TRUE(L.materials[std::size_t(used)].specular);
  EXPECT_EQ(L.materials[std::size_t(used)].specular->size(), (std::size_t(1) << cfg.unit_frac_bits) + 1);
  EXPECT_FALSE(L.materials[std::size_t(unused)].specular);
  EXPECT_NE(L.materials[std::size_t(unused)].color[1], 0);  // its colour is still quantised
}
