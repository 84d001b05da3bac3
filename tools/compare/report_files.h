// The comparison's data files: DIR/compare.json (the runs, the equal-error and equal-cost
// tables, the renderer and configuration) and DIR/compare.csv (one line per run).
#pragma once
#include <string>

#include <nlohmann/json.hpp>

#include "tools/compare/compare_plan.h"
#include "tools/compare/facet_levels.h"
#include "tools/compare/quadric_runs.h"

namespace qacc::compare {

// Writes text to path; throws std::runtime_error when it cannot.
void writeText(const std::string& path, const std::string& text);

void writeCompareJson(const CompareOptions& o, const ComparePlan& plan, const QuadricRuns& quadrics,
                      const FacetRuns& facets, const nlohmann::json& jEqual, const nlohmann::json& jCost);
void writeCompareCsv(const CompareOptions& o, const Scene& scene, const QuadricRuns& quadrics, const FacetRuns& facets);

}  // namespace qacc::compare
