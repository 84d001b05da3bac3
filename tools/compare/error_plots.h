// The SVG plots of the comparison (tools/report/svg_plot.h): every metric against the
// primitive count (DIR/error_vs_triangles.svg) and, when every run has modeled cycles,
// against the cycles (DIR/error_vs_cycles.svg); facets as a series, the accelerator as a
// point and a level line.
#pragma once
#include <string>
#include <vector>

#include "tools/compare/compare_row.h"

namespace qacc::compare {

// Returns whether the cycles plot was written.
bool writeErrorPlots(const std::string& outDir, const std::string& sceneName, const std::string& shadingUsed,
                     const Row& hw, const std::vector<Row>& facets);

}  // namespace qacc::compare
