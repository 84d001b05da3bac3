#include "modeling/tessellation/exact_facets.h"

#include <algorithm>
#include <stdexcept>
#include <utility>

namespace qacc::tess {

ExactSurfaceMesh tessellateExact(const ExactSurface& surface, std::size_t pieces, const TessellationOptions& options,
                                 const ScreenView* view) {
  pieces = std::max<std::size_t>(pieces, 1);
  double bound = options.chord_error;
  if (options.pixel_error > 0) {
    if (!view) throw std::invalid_argument("tessellation: pixel_error needs the scene's view");
    bound = options.pixel_error / view->maxPixelsPerUnit(surface.bounds());
  }
  if (bound <= 0) return surface.tessellate(std::size_t(std::max(2, options.triangles)) * pieces);
  std::size_t budget = 64 * pieces;
  ExactSurfaceMesh m = surface.tessellate(budget);
  while (m.max_error > bound && 4 * budget <= std::size_t(options.max_triangles) * pieces) {
    budget *= 4;
    ExactSurfaceMesh finer = surface.tessellate(budget);
    const bool same = finer.grid == m.grid;  // the finest grid is reached
    m = std::move(finer);
    if (same) break;
  }
  return m;
}

TriangleMesh3 exactSurfaceFacets(ExactSurfaceMesh&& em, int object, int material, int primitive) {
  TriangleMesh3 t;
  t.positions = std::move(em.positions);
  t.normals = std::move(em.normals);
  t.triangles = std::move(em.triangles);
  const std::size_t n = t.size();
  t.object.assign(n, object);
  t.material.assign(n, material);
  t.primitive.assign(n, primitive);
  return t;
}

}  // namespace qacc::tess
