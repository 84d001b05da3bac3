#include "raster/pixel/facet_shading.h"

#include <stdexcept>

namespace qacc {

FacetShading parseFacetShading(const std::string& name) {
  if (name.empty() || name == "gouraud") return FacetShading::Gouraud;
  if (name == "pixel" || name == "per-pixel" || name == "phong") return FacetShading::PerPixel;
  throw std::invalid_argument("unknown facet shading '" + name + "' (gouraud or pixel)");
}

const char* facetShadingName(FacetShading s) { return s == FacetShading::Gouraud ? "gouraud" : "pixel"; }

}  // namespace qacc
