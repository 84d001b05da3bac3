#include "tools/compare/compare.h"

#include <cstdio>
#include <filesystem>

#include "tools/compare/equal_cost.h"
#include "tools/compare/equal_error.h"
#include "tools/compare/error_plots.h"
#include "tools/compare/facet_levels.h"
#include "tools/compare/quadric_runs.h"
#include "tools/compare/report_files.h"
#include "tools/compare/results_table.h"
#include "tools/compare/side_by_side.h"

namespace qacc::compare {

void runCompare(const CompareOptions& o) {
  namespace fs = std::filesystem;
  const ComparePlan plan = planCompare(o);
  const QuadricRuns quadrics = renderQuadrics(plan, o.threads);
  const FacetRuns facets = renderFacetLevels(plan, o, quadrics.ref);

  printResultsTable(plan.scene, quadrics, facets);
  const nlohmann::json jEqual = equalErrorTable(quadrics.hw, facets.rows);
  const nlohmann::json jCost = equalCostTable(quadrics.hw, facets.rows);

  writeCompareJson(o, plan, quadrics, facets, jEqual, jCost);
  writeCompareCsv(o, plan.scene, quadrics, facets);
  const Row& shown = facets.rows[shownFacetLevel(jEqual, facets.rows)];
  writeSideBySide((fs::path(o.out_dir) / "side_by_side.png").string(), quadrics.ref, quadrics.hw, shown);
  const bool anyCycles = writeErrorPlots(o.out_dir, plan.scene.name, facets.shading_used, quadrics.hw, facets.rows);
  std::printf("\nwrote %s/{compare.json, compare.csv, side_by_side.png (facets level %d), error_vs_triangles.svg%s}\n",
              o.out_dir.c_str(), shown.level, anyCycles ? ", error_vs_cycles.svg" : "");
}

}  // namespace qacc::compare
