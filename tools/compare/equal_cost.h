// The equal-cost table: the facet level nearest (in log scale) to the accelerator's
// primitive count, modeled cycles and host time, with both sides' errors. Printed on stdout
// and returned as the report's "equal_cost" object.
#pragma once
#include <vector>

#include <nlohmann/json.hpp>

#include "tools/compare/compare_row.h"

namespace qacc::compare {

nlohmann::json equalCostTable(const Row& hw, const std::vector<Row>& facets);

}  // namespace qacc::compare
