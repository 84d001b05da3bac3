// The first table of `qacc compare` on stdout: the scene and the facet renderer, then one
// row per run (the accelerator, then the facets per level) with sizes, times, cycles and
// errors.
#pragma once
#include "tools/compare/compare_plan.h"
#include "tools/compare/facet_levels.h"
#include "tools/compare/quadric_runs.h"

namespace qacc::compare {

void printResultsTable(const Scene& scene, const QuadricRuns& quadrics, const FacetRuns& facets);

}  // namespace qacc::compare
