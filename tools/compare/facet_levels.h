// The facets at every tessellation level: the scene tessellated and drawn through OSMesa
// (image, host time), measured against the reference, and the same triangles through the
// accelerator's flat-facet path (modeled cycles; skipped with --no-facet-cycles or above
// max_cycle_triangles). Objects with an exact surface are triangles of the true surface.
#pragma once
#include <cstddef>
#include <string>
#include <vector>

#include "raster/image/frame_buffer.h"
#include "tools/compare/compare_plan.h"
#include "tools/compare/compare_row.h"

namespace qacc::compare {

struct FacetRuns {
  std::vector<Row> rows;  // one per level, ascending
  std::string gl_renderer, gl_version, shading_used, note;
  std::size_t exact_surfaces = 0;
};

FacetRuns renderFacetLevels(const ComparePlan& plan, const CompareOptions& o, const FrameBuffer& ref);

}  // namespace qacc::compare
