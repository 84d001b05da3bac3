// DIR/side_by_side.png: top, reference | quadrics | facets; bottom, the luma-error heat maps
// of the quadrics and of the facets | the facets' coverage errors (red: wrong object,
// yellow: pinhole, cyan: spurious) over the dimmed reference. The facets shown are the level
// that reaches the accelerator's PSNR, else the finest.
#pragma once
#include <string>
#include <vector>

#include <nlohmann/json.hpp>

#include "raster/image/frame_buffer.h"
#include "tools/compare/compare_row.h"

namespace qacc::compare {

// Index in `facets` of the level shown (jEqual: the equal-error table).
std::size_t shownFacetLevel(const nlohmann::json& jEqual, const std::vector<Row>& facets);

void writeSideBySide(const std::string& path, const FrameBuffer& ref, const Row& hw, const Row& facets);

}  // namespace qacc::compare
