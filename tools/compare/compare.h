// `qacc compare`: quadrics against triangles (design §4), as stages — plan (compare_plan.h),
// the reference and the accelerator (quadric_runs.h), the facets per tessellation level
// (facet_levels.h), the tables (results_table.h, equal_error.h, equal_cost.h), and the
// report (report_files.h, side_by_side.h, error_plots.h). docs/COMPARE.md describes the
// output.
#pragma once
#include "tools/compare/compare_plan.h"

namespace qacc::compare {

void runCompare(const CompareOptions& o);

}  // namespace qacc::compare
