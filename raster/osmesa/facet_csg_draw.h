// How the facet renderer (osmesa_renderer.h) draws a scene with csg objects through OpenCSG
// (docs/CSG.md, "Triangles"): the triangles of primitives outside csg objects with the
// ordinary depth test; then, per csg object, each product of its normal form
// (modeling/csg/csg_normal_form.h; leaves intersected, complemented leaves subtracted)
// through OpenCSG's Goldfeather algorithm, which sets the depth buffer to the product's
// visible depth where it is nearer, and the product's leaves drawn again with GL_EQUAL,
// which colours (or labels, in the id pass) the surface that won. Each leaf is drawn from
// its closed tessellation (surface and caps). Built only with OpenCSG (QACC_HAVE_OPENCSG).
#pragma once
#include <functional>
#include <vector>

#include "modeling/csg/csg_normal_form.h"
#include "modeling/scene/scene.h"
#include "modeling/tessellation/tessellation.h"

namespace qacc {

class FacetCsgDraw {
 public:
  // `mesh` as drawn by the renderer: triangle t is vertices 3t, 3t + 1, 3t + 2 of its arrays.
  FacetCsgDraw(const Scene& scene, const TriangleMesh3& mesh);
  // Draws every triangle from the caller's vertex arrays, which `bindArrays` binds (OpenCSG
  // draws with arrays of its own); `programOff` and `programOn` unbind and rebind the
  // caller's shader around OpenCSG's own passes.
  void draw(const std::function<void()>& bindArrays, const std::function<void()>& programOff,
            const std::function<void()>& programOn) const;

 private:
  std::vector<unsigned> plain_;                 // vertices of triangles outside csg objects
  std::vector<std::vector<unsigned>> leaf_;     // per primitive: its vertices (csg leaves only)
  std::vector<CsgNormalForm> forms_;            // per csg object
};

}  // namespace qacc
