// Cost model: gate equivalents follow the configured widths and counts.
#include <gtest/gtest.h>

#include "hw_model/report/cost_model.h"
#include "hw_model/config/hw_config.h"
#include "hw_model/report/scene_needs.h"
#include "modeling/geometry/natural_quadrics.h"

using namespace qacc;

namespace {
HwConfig shipped(const char* n) {
  return loadHwConfig(std::string(QACC_SOURCE_DIR) + "/hw_model/configs/" + n + ".json");
}
const UnitCost& unit(const CostModel& m, const std::string& name) {
  for (const UnitCost& u : m.units)
    if (u.unit == name) return u;
  throw std::runtime_error("no unit " + name);
}
}  // namespace

TEST(CostModel, TotalIsTheSumOfItsUnits) {
  const CostModel m = CostModel::of(HwConfig());
  double sum = 0;
  for (const UnitCost& u : m.units) {
    EXPECT_GT(u.ge_each, 0) << u.unit;
    sum += u.ge_each * u.copies;
  }
  EXPECT_DOUBLE_EQ(m.totalGe(), sum);
  EXPECT_EQ(m.zbufferBitsPerPixel, HwConfig().zbuffer_bits);
}

TEST(CostModel, GrowsWithWidthsAndCounts) {
  HwConfig a;
  const CostModel base = CostModel::of(a);
  HwConfig wider = a;
  wider.delta_bits += 16;  // a wider square-root extractor
  EXPECT_GT(unit(CostModel::of(wider), "pixel_pipeline").ge_each, unit(base, "pixel_pipeline").ge_each);
  HwConfig more = a;
  more.pipelines = 2 * a.pipelines;
  EXPECT_EQ(unit(CostModel::of(more), "pixel_pipeline").copies, 2 * a.pipelines);
  EXPECT_GT(CostModel::of(more).totalGe(), base.totalGe());
  HwConfig clip = a;
  clip.clip_evaluators = 2 * a.clip_evaluators;
  EXPECT_GT(unit(CostModel::of(clip), "pixel_pipeline").ge_each, unit(base, "pixel_pipeline").ge_each);
  HwConfig recip = a;
  recip.depth_variant = DepthVariant::Reciprocal;  // two multipliers instead of two dividers
  EXPECT_LT(unit(CostModel::of(recip), "pixel_pipeline").ge_each, unit(base, "pixel_pipeline").ge_each);
}

TEST(CostModel, ShippedConfigurationsAreOrderedByCost) {
  const double minimal = CostModel::of(shipped("minimal")).totalGe();
  const double def = CostModel::of(shipped("default")).totalGe();
  const double wide = CostModel::of(shipped("wide")).totalGe();
  EXPECT_LT(minimal, def);
  EXPECT_LT(def, wide);
}

TEST(CostModel, TheConfigurationASceneNeedsDropsTheUnitsItDoesNotUse) {
  const HwConfig cfg;
  const CostModel full = CostModel::of(cfg);
  // Everything used (solids, facets, K planes or more): the needed configuration is the full one.
  SceneNeeds all;
  all.solids = all.facets = true;
  all.max_planes = cfg.clip_evaluators + 3;
  EXPECT_DOUBLE_EQ(CostModel::of(cfg, &all).totalGe(), full.totalGe());
  // Spheres only: no cap logic, no clip evaluators, no facet path, smaller descriptors.
  Scene spheres;
  spheres.primitives.push_back(makeSphere({0, 0, 0}, 1));
  const SceneNeeds none = SceneNeeds::of(spheres);
  EXPECT_FALSE(none.solids);
  EXPECT_FALSE(none.facets);
  EXPECT_EQ(none.max_planes, 0);
  const CostModel bare = CostModel::of(cfg, &none);
  EXPECT_LT(unit(bare, "pixel_pipeline").ge_each, unit(full, "pixel_pipeline").ge_each);
  EXPECT_LT(unit(bare, "host_interface").ge_each, unit(full, "host_interface").ge_each);
  EXPECT_EQ(unit(bare, "shading").ge_each, unit(full, "shading").ge_each);
  // Each unit on its own lowers the pipeline's cost.
  SceneNeeds noCaps = all, noFacets = all, twoPlanes = all;
  noCaps.solids = false;
  noFacets.facets = false;
  twoPlanes.max_planes = 2;
  for (const SceneNeeds* n : {&noCaps, &noFacets, &twoPlanes})
    EXPECT_LT(unit(CostModel::of(cfg, n), "pixel_pipeline").ge_each, unit(full, "pixel_pipeline").ge_each);
  // A solid clipped cylinder needs caps and its planes.
  Scene solid;
  Primitive cyl = makeSphere({0, 0, 0}, 1);
  cyl.solid = true;
  cyl.clip.push_back(HalfSpace(Eigen::Vector4d(0, 0, 1, -0.5)));
  solid.primitives.push_back(cyl);
  const SceneNeeds s = SceneNeeds::of(solid);
  EXPECT_TRUE(s.solids);
  EXPECT_EQ(s.max_planes, 1);
}
