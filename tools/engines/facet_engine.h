// The facet engine of `qacc render --engine facets --level N [--shading gouraud|pixel]`:
// tessellate every primitive (modeling/tessellation.h; objects with an exact surface are
// tessellated from that surface, not from their pieces), draw the triangles with OSMesa
// (raster/osmesa_renderer.h). Without OSMesa in the build it refuses with a clear message.
#pragma once
#include <string>

#include "modeling/tessellation/tessellation.h"
#include "raster/osmesa/osmesa_renderer.h"
#include "tools/engines/engine.h"

namespace qacc {

constexpr int kDefaultFacetLevel = 128;  // triangles per primitive when --level is not given

struct FacetRun {
  TessellationReport tessellation;
  double tessellate_ms = 0;
  FacetRenderResult render;
};

// Renders with the facet engine if `engine` is "facets" (returns false otherwise).
bool runFacetEngine(const std::string& engine, const Scene& scene, const EngineOptions& options, EngineResult& out);
// The same with everything it measured (for compare). Also returns the triangles.
// Refuses (std::invalid_argument) a tessellation whose surface triangles, primitives x level,
// exceed `max_triangles` (caps come on top), before building it.
FacetRun renderFacetScene(const Scene& scene, int level, FacetShading shading, int threads, std::size_t max_triangles,
                          TriangleMesh3* mesh = nullptr);
// The tessellation options of a level (triangles per primitive) or, when pixelError > 0, of
// a screen-space tolerance: every primitive to at most pixelError pixels of projected chord
// error in the scene's view (modeling/tessellation: TessellationOptions::pixel_error).
TessellationOptions facetTessellationOptions(int level, double pixelError);
// The same run from explicit options. With a pixel error the count is known only once built:
// a mesh over `max_triangles` is refused after tessellation, before drawing.
FacetRun renderFacetScene(const Scene& scene, const TessellationOptions& options, FacetShading shading, int threads,
                          std::size_t max_triangles, TriangleMesh3* mesh = nullptr);
// The achieved projected chord error of a pixel-error tessellation (max, mean; pixels).
double achievedMaxPixelError(const TessellationReport& report);
double achievedMeanPixelError(const TessellationReport& report);

}  // namespace qacc
