// Shading modes of the facet renderer (osmesa_renderer.h): per-vertex Gouraud as 1990s
// triangle hardware did, or per-pixel lighting as a modern GPU does.
#pragma once
#include <string>

namespace qacc {

enum class FacetShading { Gouraud, PerPixel };
// "gouraud" | "pixel" (also "per-pixel", "phong"); throws std::invalid_argument otherwise.
FacetShading parseFacetShading(const std::string& name);
const char* facetShadingName(FacetShading s);

}  // namespace qacc
