// Cost model: gate equivalents follow the configured widths and counts.
#include <gtest/gtest.h>

#include "hw_model/report/cost_model.h"
#include "hw_model/config/hw_config.h"

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
