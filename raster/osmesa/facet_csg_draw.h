// How the facet renderer (osmesa_renderer.h) draws a scene with csg objects through OpenCSG
// (docs/CSG.md, "Triangles"): the triangles of primitives outside csg objects with the
// ordinary depth test; then, per csg object, each product of its normal form
// (modeling/csg/csg_normal_form.h; leaves intersected, complemented leaves subtracted)
// through OpenCSG's Goldfeather algorithm, which sets the depth buffer to the product's
// visible depth where it is nearer, and the product's leaves drawn again with GL_EQUAL,
// which colours (or labels, in the id pass) the surface that won. Each leaf is drawn from
// its closed tessellation (surface and caps).
//
// Box pruning (on unless FacetCsgDraw is told otherwise): every leaf's box in normalised
// device coordinates, from its projected triangles and widened by two pixels and 1e-5 in
// depth, is given to OpenCSG (Primitive::setBoundingBox), which scissors each product to
// its positive leaves' common screen box and skips the parity tests of subtracted leaves
// whose box misses; and each product is pruned by these boxes first
// (modeling/csg/csg_product_pruning.h): a product whose positive leaves' boxes do not meet
// is not drawn, a complemented leaf whose box misses them is left out. Neither changes
// which surface wins a pixel. Built only with OpenCSG (QACC_HAVE_OPENCSG).
#pragma once
#include <cstddef>
#include <functional>
#include <string>
#include <vector>

#include <Eigen/Geometry>

#include "modeling/csg/csg_normal_form.h"
#include "modeling/scene/scene.h"
#include "modeling/tessellation/tessellation.h"

namespace qacc {

// What the box pruning did to the scene's products (sums over its csg objects).
struct FacetCsgPruning {
  std::size_t products = 0;             // products of the normal forms
  std::size_t skipped = 0;              // not drawn: their positive leaves' boxes do not meet
  std::size_t literals_dropped = 0;     // complemented leaves left out of the products drawn
  std::size_t single_leaf_products = 0; // drawn products left with one leaf
  std::string line() const;             // "csg: N products, ..." for the engine's notes
};

class FacetCsgDraw {
 public:
  // `mesh` as drawn by the renderer: triangle t is vertices 3t, 3t + 1, 3t + 2 of its arrays;
  // the scene's camera on its image size gives the leaves' boxes. `boxPruning` false draws
  // every product whole over the whole viewport (to test that the pruning changes nothing).
  FacetCsgDraw(const Scene& scene, const TriangleMesh3& mesh, bool boxPruning = true);
  // Draws every triangle from the caller's vertex arrays, which `bindArrays` binds (OpenCSG
  // draws with arrays of its own); `programOff` and `programOn` unbind and rebind the
  // caller's shader around OpenCSG's own passes.
  void draw(const std::function<void()>& bindArrays, const std::function<void()>& programOff,
            const std::function<void()>& programOn) const;
  const FacetCsgPruning& pruning() const { return pruning_; }

 private:
  std::vector<unsigned> plain_;                 // vertices of triangles outside csg objects
  std::vector<std::vector<unsigned>> leaf_;     // per primitive: its vertices (csg leaves only)
  std::vector<Eigen::AlignedBox3d> box_;        // per primitive: its leaf's box in NDC (csg leaves only)
  bool boxPruning_ = true;
  std::vector<CsgProduct> products_;            // the products drawn, of every csg object in order
  FacetCsgPruning pruning_;
};

}  // namespace qacc
