// Facets of objects with an exact surface (exact_surface.h: algebraic surfaces, which the
// reference ray-casts): they are tessellated from that surface, not from their quadric
// pieces — the surface's own triangles (marching tetrahedra of the true surface), about
// `triangles` per cell of the object's model (SceneObject::model_cells: the algebraic
// modeler's Kuhn tetrahedra at its level, whether or not view culling built them, so that
// the mesh does not depend on the view the scene was culled for; the object's piece count
// when the modeler gives no cells), or with `chord_error` the budget quadrupled from 64 per
// cell until the sampled distance to the true surface is at most the bound (up to the
// finest marching grid).
#pragma once
#include <cstddef>

#include "modeling/geometry/exact_surface.h"
#include "modeling/tessellation/screen_error.h"
#include "modeling/tessellation/tessellation.h"

namespace qacc::tess {

// The triangles of an object's exact surface, at the budget of `pieces` cells or pieces; with
// options.pixel_error, the budget quadrupled until the measured distance to the surface
// times the largest pixels per world unit over its bounds is at most the bound (`view`
// required then).
ExactSurfaceMesh tessellateExact(const ExactSurface& surface, std::size_t pieces, const TessellationOptions& options,
                                 const ScreenView* view = nullptr);

// The object's exact surface as a facet mesh: every triangle tagged with the object, the
// material and the primitive (the object's first piece) it stands for.
TriangleMesh3 exactSurfaceFacets(ExactSurfaceMesh&& em, int object, int material, int primitive);

}  // namespace qacc::tess
