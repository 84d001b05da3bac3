// One measured run of the comparison: the accelerator on the quadrics, or the facets at one
// tessellation setting (a tolerance in pixels or a level) — its size, times, modeled cycles, image and errors.
#pragma once
#include <cstddef>
#include <cstdint>
#include <sstream>
#include <string>

#include "raster/image/frame_buffer.h"
#include "tools/compare/image_metrics.h"

namespace qacc::compare {

struct Row {
  std::string engine;  // "hw" or "facets"
  int level = 0;               // facets by level: triangles per primitive (0: by tolerance)
  double tolerance_px = 0;     // facets by tolerance: projected chord error asked, pixels (0: by level)
  double achieved_px = 0;      // facets by tolerance: max projected chord error achieved (tessellation's own measure)
  std::size_t primitives = 0;  // quadrics or triangles
  double host_ms = 0;          // total host time of the engine (facets: tessellation + GL)
  double draw_ms = 0;          // facets: GL draw + glFinish of the colour pass only (hw: host_ms)
  double context_ms = 0;       // facets: OSMesa context creation
  double upload_ms = 0;        // facets: vertex shading, arrays, state, warm-up draw
  double gl_ms = 0;            // facets: everything OSMesa did (context, arrays, both passes, read back)
  double tess_ms = 0;          // facets: tessellation (incl. chord-error measurement)
  std::uint64_t cycles = 0;    // modeled cycles (0 = not measured)
  double modeled_ms = 0;
  double chord_error = 0;      // facets: max chord error (world units)
  int exact_grid = 0;          // facets: marching grid of the exact surfaces (cubes per axis, 0 = none)
  // facets: shared planes and pieces left as tessellated, unstitched (TessellationReport): where cracks can show
  std::size_t unstitched_planes = 0, unstitched_pieces = 0;
  Metrics m;
  FrameBuffer fb;
  std::string setting() const {  // "hw", "eps 0.5 px" or "level 128"
    if (engine != "facets") return engine;
    if (level > 0) return "level " + std::to_string(level);
    std::ostringstream s;
    s << "eps " << tolerance_px << " px";
    return s.str();
  }
};

}  // namespace qacc::compare
