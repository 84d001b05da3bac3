// The equal-cost table: the facet setting nearest (in log scale) to the accelerator's
// primitive count, modeled cycles (facet path against quadric path on the same accelerator)
// and host time (hw's frame against llvmpipe's draw alone: GL context creation, upload and
// tessellation are timed apart), with both sides' errors. Printed on stdout
// and returned as the report's "equal_cost" object.
#pragma once
#include <vector>

#include <nlohmann/json.hpp>

#include "tools/compare/compare_row.h"

namespace qacc::compare {

nlohmann::json equalCostTable(const Row& hw, const std::vector<Row>& facets);

}  // namespace qacc::compare
