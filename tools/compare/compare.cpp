#include "tools/compare/compare.h"

#include <cstdio>
#include <filesystem>

#include "tools/compare/crossover.h"
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
  if (!plan.sizes.empty()) {  // the crossover instead of the comparison at one size
    runCrossover(plan, o);
    return;
  }
  const QuadricRuns quadrics = renderQuadrics(plan, o.threads);
  const FacetRuns facets = renderFacetLevels(plan, o, quadrics.ref);

  printResultsTable(plan.scene, quadrics, facets);
  const nlohmann::json jEqual = equalErrorTable(quadrics.hw, facets.rows);
  const nlohmann::json jCost = equalCostTable(quadrics.hw, facets.rows);

  writeCompareJson(o, plan, quadrics, facets, jEqual, jCost);
  writeCompareCsv(o, plan.scene, quadrics, facets);
  const Row& shown = facets.rows[shownFacetLevel(jEqual, facets.rows)];
  SideBySideInfo info;
  info.scene = plan.scene.name;
  info.hw_config = o.config_path.empty() ? "default configuration" : o.config_path;
  info.facet_shading = facets.shading_used;
  info.gl_renderer = facets.gl_renderer;
  info.quadric_primitives = int(plan.scene.primitives.size());
  writeSideBySidePanels(o.out_dir, info, quadrics.ref, quadrics.hw, shown);
  const std::string composed = composeSideBySide(o.out_dir);
  const bool anyCycles = writeErrorPlots(o.out_dir, plan.scene.name, facets.shading_used, quadrics.hw, facets.rows);
  std::printf("\nwrote %s/{compare.json, compare.csv, side_by_side.json, panels/, %s(facets %s), "
              "error_vs_triangles.svg%s}\n",
              o.out_dir.c_str(), composed.empty() ? "side_by_side.png " : "", shown.setting().c_str(),
              anyCycles ? ", error_vs_cycles.svg" : "");
  if (!composed.empty())
    std::printf("note: side_by_side.png not composed: %s (run tools/compose_side_by_side.py %s)\n", composed.c_str(),
                o.out_dir.c_str());
}

}  // namespace qacc::compare
