// DIR/side_by_side.png, a figure a newcomer can read: top, reference | quadrics (the
// accelerator, its configuration) | facets (triangle count, tolerance); bottom, the luma-error
// maps of the quadrics and of the facets (colour scale, PSNR) | the facets' coverage errors
// (red: wrong object, yellow: pinhole, cyan: spurious) over the dimmed reference. The C++
// writes the six panels (DIR/panels/*.png) and DIR/side_by_side.json describing them (titles,
// settings, metrics); tools/compose_side_by_side.py composes the labelled figure with
// matplotlib. The facets shown are the first setting that reaches the accelerator's
// silhouette error, else the finest.
#pragma once
#include <string>
#include <vector>

#include <nlohmann/json.hpp>

#include "raster/image/frame_buffer.h"
#include "tools/compare/compare_row.h"

namespace qacc::compare {

// Index in `facets` of the setting shown (jEqual: the equal-error table).
std::size_t shownFacetLevel(const nlohmann::json& jEqual, const std::vector<Row>& facets);

struct SideBySideInfo {
  std::string scene, hw_config, facet_shading, gl_renderer;
  int quadric_primitives = 0;
};

// Writes the panels and DIR/side_by_side.json.
void writeSideBySidePanels(const std::string& dir, const SideBySideInfo& info, const FrameBuffer& ref, const Row& hw,
                           const Row& facets);
// Runs tools/compose_side_by_side.py DIR (python3 with matplotlib); returns "" when
// DIR/side_by_side.png was written, else why not.
std::string composeSideBySide(const std::string& dir);

}  // namespace qacc::compare
