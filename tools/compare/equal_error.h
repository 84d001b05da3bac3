// The equal-error table: per metric, the smallest tessellation that reaches the accelerator's
// error, interpolated between the measured settings (equal_error_point.h: never more than
// one step beyond the finest measured; else "not reached" with the finest measured), with its
// triangles, facet-path cycles and llvmpipe draw time taken at the same point. Printed on
// stdout and returned as the report's "equal_error" array.
#pragma once
#include <vector>

#include <nlohmann/json.hpp>

#include "tools/compare/compare_row.h"
#include "tools/compare/equal_error_point.h"
#include "tools/compare/image_metrics.h"

namespace qacc::compare {

// The scale on which a metric is interpolated against log triangles.
ErrorScale errorScale(const MetricDef& d);
// The equal-error point of one metric over the facet rows (coarse to fine).
EqualErrorPoint equalErrorOf(const MetricDef& d, const Row& hw, const std::vector<Row>& facets);
// A per-row quantity at the point; 0 (not measured) counts as missing (NaN).
double rowValueAt(const EqualErrorPoint& p, const std::vector<Row>& facets, double (*get)(const Row&));

nlohmann::json equalErrorTable(const Row& hw, const std::vector<Row>& facets);

}  // namespace qacc::compare
