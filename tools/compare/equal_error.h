// The equal-error table: per metric, the smallest tessellation no worse than the
// accelerator; when no level reaches it, the number of triangles that would, extrapolated
// from the two finest levels (error ∝ N^b for lower-better metrics, 1 − SSIM ∝ N^b, PSNR
// linear in log N). Printed on stdout and returned as the report's "equal_error" array.
#pragma once
#include <vector>

#include <nlohmann/json.hpp>

#include "tools/compare/compare_row.h"

namespace qacc::compare {

nlohmann::json equalErrorTable(const Row& hw, const std::vector<Row>& facets);

}  // namespace qacc::compare
