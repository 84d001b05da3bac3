// The crossover by screen size (`qacc compare SCENE --sizes 256x192,...,4096x3072`): the same
// view rendered at every size; at each, the facets at every tolerance (pixels, so the
// tessellation follows the size) and the quadrics on the same accelerator; the facet-path
// cycles at the accelerator's silhouette error (interpolated between tolerances,
// equal_error_point.h) over the quadric-path cycles, against the mean projected primitive
// size (pixels the reference covers per quadric primitive); and the break-even size, where
// that ratio crosses 1 (quadrics stop paying), interpolated between sizes or "not reached in
// the measured range". Writes DIR/crossover.json and DIR/crossover.csv (self-describing);
// tools/plot_crossover.py draws them.
#pragma once
#include <cstddef>
#include <vector>

#include "tools/compare/compare_plan.h"

namespace qacc::compare {

// The silhouette error the facets must reach: the accelerator's Hausdorff distance, floored
// at 1 px (the metric's resolution: 0 and 1 px both mean at most one pixel off).
double crossoverSilhouetteTarget(double hwHausdorff);

struct SizeRatio {
  double px_per_primitive = 0;  // mean projected primitive size
  double ratio = 0;             // facet cycles / quadric cycles at equal silhouette error (NaN: unknown)
};

struct BreakEven {
  bool found = false;
  double px_per_primitive = 0;  // where the ratio crosses 1 (log-log interpolation between sizes)
  bool quadrics_pay_below = false;  // the ratio is above 1 for smaller primitives than the break-even
};

// The first crossing of ratio = 1 between consecutive measured sizes (by primitive size);
// unknown ratios are skipped; never extrapolated.
BreakEven breakEven(std::vector<SizeRatio> points);

void runCrossover(const ComparePlan& plan, const CompareOptions& o);

}  // namespace qacc::compare
