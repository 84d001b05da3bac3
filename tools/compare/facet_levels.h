// The facets at every tessellation setting (a screen-space tolerance in pixels, or a level of
// triangles per primitive): the scene tessellated and drawn through OSMesa (image; context,
// upload and draw timed apart), measured against the reference, and the same triangles
// through the accelerator's flat-facet path (modeled cycles; skipped with --no-facet-cycles
// or above max_cycle_triangles). Objects with an exact surface are triangles of the true surface.
#pragma once
#include <cstddef>
#include <string>
#include <vector>

#include "modeling/scene/scene.h"
#include "raster/image/frame_buffer.h"
#include "tools/compare/compare_plan.h"
#include "tools/compare/compare_row.h"

namespace qacc::compare {

struct FacetRuns {
  std::vector<Row> rows;  // one per setting, coarse to fine
  std::string gl_renderer, gl_version, shading_used, note;
  std::size_t exact_surfaces = 0;
};

// Every setting of the plan on the plan's scene.
FacetRuns renderFacetLevels(const ComparePlan& plan, const CompareOptions& o, const FrameBuffer& ref);
// Every setting of the plan on `scene` (the plan's scene at another size, for the crossover).
FacetRuns renderFacetSettings(const Scene& scene, const ComparePlan& plan, const CompareOptions& o,
                              const FrameBuffer& ref);

}  // namespace qacc::compare
