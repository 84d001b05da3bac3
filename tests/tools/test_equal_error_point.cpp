// The equal-error selection of `qacc compare` and its crossover (tools/compare/
// equal_error_point.h, crossover.h) on synthetic measurements: it never reports a setting it
// did not measure, never goes more than one step beyond the finest, and says "not reached"
// otherwise; the option parsers of compare's tolerances, levels and sizes.
#include <gtest/gtest.h>

#include <cmath>
#include <random>
#include <stdexcept>

#include "tools/cli/list_option.h"
#include "tools/compare/compare_plan.h"
#include "tools/compare/crossover.h"
#include "tools/compare/equal_error_point.h"

using namespace qacc;
using namespace qacc::compare;

namespace {

// Silhouette-like rows: error halves as the triangles double.
std::vector<MeasuredError> halving() { return {{100, 8}, {200, 4}, {400, 2}, {800, 1}}; }

}  // namespace

TEST(EqualErrorPoint, InterpolatesBetweenTheMissAndTheFirstHit) {
  const EqualErrorPoint p = equalErrorPoint(halving(), 3, false, ErrorScale::Log);
  ASSERT_EQ(p.status, EqualErrorStatus::Interpolated);
  EXPECT_EQ(p.lo, 1u);
  EXPECT_EQ(p.hi, 2u);
  EXPECT_GT(p.cost, 200);
  EXPECT_LT(p.cost, 400);
  EXPECT_NEAR(p.cost, 800.0 / 3.0, 1e-9);  // error = 800 / N on the log scale
}

TEST(EqualErrorPoint, AnExactHitIsTheMeasuredSetting) {
  const EqualErrorPoint p = equalErrorPoint(halving(), 2, false, ErrorScale::Log);
  ASSERT_EQ(p.status, EqualErrorStatus::Interpolated);
  EXPECT_EQ(p.hi, 2u);
  EXPECT_DOUBLE_EQ(p.cost, 400);
}

TEST(EqualErrorPoint, TheCoarsestReachingIsAnUpperBoundNotAnExtrapolationDown) {
  const EqualErrorPoint p = equalErrorPoint(halving(), 20, false, ErrorScale::Log);
  EXPECT_EQ(p.status, EqualErrorStatus::AtCoarsest);
  EXPECT_DOUBLE_EQ(p.cost, 100);
}

TEST(EqualErrorPoint, AtMostOneStepBeyondTheFinest) {
  // One step beyond 800 is 1600 (error 0.5): 0.6 is within it, 0.4 is not.
  const EqualErrorPoint within = equalErrorPoint(halving(), 0.6, false, ErrorScale::Log);
  ASSERT_EQ(within.status, EqualErrorStatus::Extrapolated);
  EXPECT_GT(within.cost, 800);
  EXPECT_LE(within.cost, 1600);
  EXPECT_NEAR(within.cost, 800 / 0.6, 1e-6);
  const EqualErrorPoint beyond = equalErrorPoint(halving(), 0.4, false, ErrorScale::Log);
  EXPECT_EQ(beyond.status, EqualErrorStatus::NotReached);
  EXPECT_TRUE(std::isnan(beyond.cost));
  EXPECT_EQ(beyond.finest, 3u);  // the answer given instead: the finest measured
}

TEST(EqualErrorPoint, AFlatOrWorseningTrendIsNotReached) {
  const EqualErrorPoint flat = equalErrorPoint({{100, 2}, {200, 2}}, 1.9, false, ErrorScale::Log);
  EXPECT_EQ(flat.status, EqualErrorStatus::NotReached);
  const EqualErrorPoint worse = equalErrorPoint({{100, 2}, {200, 3}}, 1, false, ErrorScale::Log);
  EXPECT_EQ(worse.status, EqualErrorStatus::NotReached);
}

TEST(EqualErrorPoint, PsnrIsHigherBetterAndLinearInLogTriangles) {
  // 30 dB at 100, 36 dB at 400: 33 dB at 200.
  const EqualErrorPoint p = equalErrorPoint({{100, 30}, {400, 36}}, 33, true, ErrorScale::Linear);
  ASSERT_EQ(p.status, EqualErrorStatus::Interpolated);
  EXPECT_NEAR(p.cost, 200, 1e-9);
  // 51 dB is 2.5 steps beyond: not reached (the old table extrapolated it to millions).
  EXPECT_EQ(equalErrorPoint({{100, 30}, {400, 36}}, 51, true, ErrorScale::Linear).status,
            EqualErrorStatus::NotReached);
}

TEST(EqualErrorPoint, AZeroTargetFallsBackToTheLinearScale) {
  const EqualErrorPoint p = equalErrorPoint({{100, 2}, {200, 1}, {400, 0}}, 0, false, ErrorScale::Log);
  ASSERT_EQ(p.status, EqualErrorStatus::Interpolated);
  EXPECT_DOUBLE_EQ(p.cost, 400);
  // 110 → 51 pixels would reach 0 within a step on a straight line, but no power law does.
  EXPECT_EQ(equalErrorPoint({{13769, 110}, {40690, 51}}, 0, false, ErrorScale::Log).status,
            EqualErrorStatus::NotReached);
}

TEST(EqualErrorPoint, UnmeasuredSettingsAreSkippedAndNothingMeasuredIsRefused) {
  const EqualErrorPoint p = equalErrorPoint({{100, 8}, {200, NAN}, {400, 2}}, 3, false, ErrorScale::Log);
  ASSERT_EQ(p.status, EqualErrorStatus::Interpolated);
  EXPECT_EQ(p.lo, 0u);
  EXPECT_EQ(p.hi, 2u);
  EXPECT_THROW(equalErrorPoint({{100, NAN}}, 1, false, ErrorScale::Log), std::invalid_argument);
}

TEST(EqualErrorPoint, RandomRowsNeverGiveAnUnmeasuredSettingOrMoreThanOneStep) {
  std::mt19937 rng(12);
  std::uniform_real_distribution<double> u(0, 1);
  for (int trial = 0; trial < 2000; ++trial) {
    std::vector<MeasuredError> m;
    double cost = 10 + 100 * u(rng);
    for (int i = 0, n = 1 + int(u(rng) * 6); i < n; ++i) {
      m.push_back({cost, 20 * u(rng)});
      cost *= 1.2 + 3 * u(rng);
    }
    const double target = 20 * u(rng);
    const EqualErrorPoint p = equalErrorPoint(m, target, false, ErrorScale::Log);
    ASSERT_LT(p.lo, m.size());
    ASSERT_LT(p.hi, m.size());
    switch (p.status) {
      case EqualErrorStatus::AtCoarsest:
        EXPECT_LE(m[p.lo].error, target);
        EXPECT_EQ(p.cost, m[p.lo].cost);
        break;
      case EqualErrorStatus::Interpolated:
        EXPECT_EQ(p.hi, p.lo + 1);
        EXPECT_LE(m[p.hi].error, target);  // the finer bracket was measured and reaches it
        EXPECT_GT(m[p.lo].error, target);
        EXPECT_GE(p.cost, m[p.lo].cost * (1 - 1e-12));
        EXPECT_LE(p.cost, m[p.hi].cost * (1 + 1e-12));
        break;
      case EqualErrorStatus::Extrapolated: {
        const double step = m.back().cost / m[m.size() - 2].cost;
        EXPECT_GT(p.cost, m.back().cost);
        EXPECT_LE(p.cost, m.back().cost * step * (1 + 1e-12));
        for (const auto& x : m) EXPECT_GT(x.error, target);
        break;
      }
      case EqualErrorStatus::NotReached:
        EXPECT_TRUE(std::isnan(p.cost));
        EXPECT_EQ(p.finest, m.size() - 1);
        for (const auto& x : m) EXPECT_GT(x.error, target);
        break;
    }
  }
}

TEST(EqualErrorPoint, QuantitiesAreTakenAtTheSamePoint) {
  const EqualErrorPoint p = equalErrorPoint(halving(), 3, false, ErrorScale::Log);
  const std::vector<double> cycles = {1e5, 2e5, 4e5, 8e5};  // proportional to the triangles
  EXPECT_NEAR(atPoint(p, cycles), 1e5 * p.cost / 100, 1e-3);
  const EqualErrorPoint none = equalErrorPoint(halving(), 0.1, false, ErrorScale::Log);
  EXPECT_EQ(atPoint(none, cycles), 8e5);  // the finest measured
}

TEST(BreakEven, InterpolatesTheCrossingOfOneAndSaysWhenThereIsNone) {
  const BreakEven b = breakEven({{10, 4}, {100, 2}, {1000, 0.5}, {10000, 0.25}});
  ASSERT_TRUE(b.found);
  EXPECT_TRUE(b.quadrics_pay_below);
  EXPECT_NEAR(b.px_per_primitive, std::sqrt(100.0 * 1000.0), 1e-6);  // log-log halfway
  EXPECT_FALSE(breakEven({{10, 4}, {100, 2}}).found);
  EXPECT_FALSE(breakEven({{10, 4}, {100, NAN}, {1000, 2}}).found);
  EXPECT_FALSE(breakEven({{10, 0.5}}).found);
  EXPECT_DOUBLE_EQ(crossoverSilhouetteTarget(0), 1);
  EXPECT_DOUBLE_EQ(crossoverSilhouetteTarget(1.41), 1.41);
}

TEST(CompareOptions, TolerancesAreTheDefaultAndExcludeLevels) {
  CompareOptions o;
  std::vector<FacetSetting> s = facetSettings(o);
  ASSERT_EQ(s.size(), 5u);
  EXPECT_DOUBLE_EQ(s.front().tolerance_px, 4);  // coarse to fine
  EXPECT_DOUBLE_EQ(s.back().tolerance_px, 0.25);
  o.tolerances = "0.5,2,2,1";
  s = facetSettings(o);
  ASSERT_EQ(s.size(), 3u);
  EXPECT_DOUBLE_EQ(s[0].tolerance_px, 2);
  o.levels = "8,32";
  EXPECT_THROW(facetSettings(o), std::invalid_argument);
  o.tolerances.clear();
  s = facetSettings(o);
  ASSERT_EQ(s.size(), 2u);
  EXPECT_EQ(s[1].level, 32);
  for (const char* bad : {"", "1,,2", "0", "-1", "nan", "inf", "0x1p1", "1e9", "2px"}) {
    o.levels.clear();
    o.tolerances = bad;
    if (std::string(bad).empty()) continue;  // empty = the default
    EXPECT_THROW(facetSettings(o), std::invalid_argument) << bad;
  }
  EXPECT_EQ(parseDoubleListOption("0.25,4", "--t", "x", 0.01, 10), (std::vector<double>{0.25, 4}));
}

TEST(CompareOptions, SizesAreParsedSortedAndChecked) {
  const std::vector<ImageSize> s = parseSizes("512x384,256x192,512x384");
  ASSERT_EQ(s.size(), 2u);
  EXPECT_EQ(s[0].width, 256);
  EXPECT_EQ(s[1].height, 384);
  for (const char* bad : {"256", "256x", "x192", "256x192x3", "8x8", "256x192,", "16384x16384"})
    EXPECT_THROW(parseSizes(bad), std::invalid_argument) << bad;
}
