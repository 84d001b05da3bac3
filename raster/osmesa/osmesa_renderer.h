// Facet renderer through Mesa's off-screen OSMesa (design §3.3): the triangles of a
// tessellated scene drawn by gallium llvmpipe (GALLIUM_DRIVER=llvmpipe is set before the
// context is created), into a float RGBA colour buffer with a 24-bit depth buffer, with the
// scene camera's own matrices (Camera::view, Camera::projection: the same world → window map
// as the other renderers) and the lights and shading function of raster/shading.h:
//  - Gouraud (the 1990s way): shadeLinear() evaluated at every vertex on the host, the
//    linear radiance interpolated across the triangle by GL;
//  - per-pixel: the same formula (ambient + Lambert + Blinn-Phong, two-sided) in a GLSL
//    fragment shader from interpolated position and normal (needs GLSL; when the context has
//    none the result says so and falls back to Gouraud).
// Linear radiance is read back after glFinish and encoded to 8-bit sRGB on the host, rows
// flipped (GL's window y is up). A second pass draws every triangle flat with its primitive
// index + 1 as colour (lighting off) for the object / primitive id buffers; depth comes from
// the 24-bit depth buffer (window depth in [0, 1], +inf where nothing was drawn).
//
// The file osmesa_renderer.cpp is built only with OSMesa (CMake QACC_WITH_OSMESA, which
// defines QACC_HAVE_OSMESA); test facetRendererAvailable() before calling renderFacets.
#pragma once
#include <stdexcept>
#include <string>

#include "modeling/scene/scene.h"
#include "modeling/tessellation/tessellation.h"
#include "raster/pixel/facet_shading.h"
#include "raster/image/frame_buffer.h"

namespace qacc {

struct FacetRenderOptions {
  FacetShading shading = FacetShading::Gouraud;
  int threads = 0;  // llvmpipe threads (LP_NUM_THREADS, set before the first context); <= 0: Mesa's default
  // csg objects: prune the normal form's products by the leaves' boxes and give OpenCSG
  // the boxes (facet_csg_draw.h). Off only to check that the pruning changes no pixel.
  bool csg_box_pruning = true;
};

struct FacetRenderResult {
  FrameBuffer fb;
  std::string gl_renderer;  // GL_RENDERER
  std::string gl_version;   // GL_VERSION
  std::string glsl_version; // GL_SHADING_LANGUAGE_VERSION ("" when none)
  FacetShading shading_used = FacetShading::Gouraud;
  std::string note;         // e.g. why per-pixel shading fell back to Gouraud
  std::string csg_pruning;  // scenes with csg objects: what the box pruning did (FacetCsgPruning::line)
  std::size_t triangles = 0;
  // Host times, each apart, so the draw can be compared alone:
  double context_ms = 0;    // OSMesa context and buffers created and made current
  double upload_ms = 0;     // shading of vertices, arrays, GL state, shader program, and a
                            // one-triangle warm-up draw (llvmpipe compiles the state's code)
  double draw_ms = 0;       // colour pass: draw calls + glFinish (the draw alone)
  double readback_ms = 0;   // colour + depth read back, sRGB encoding
  double id_pass_ms = 0;    // id pass: draw + glFinish + read back
  double totalMs() const { return context_ms + upload_ms + draw_ms + readback_ms + id_pass_ms; }
};

#ifdef QACC_HAVE_OSMESA
constexpr bool facetRendererAvailable() { return true; }
#else
constexpr bool facetRendererAvailable() { return false; }
#endif
// csg objects through OpenCSG (facet_csg_draw.h), built when CMake finds OpenCSG and GLEW.
#ifdef QACC_HAVE_OPENCSG
constexpr bool facetCsgAvailable() { return true; }
#else
constexpr bool facetCsgAvailable() { return false; }
#endif
inline const char* facetCsgMissingMessage() {
  return "the 'facets' engine draws csg objects through OpenCSG: this qacc was built without it (install "
         "libopencsg-dev and libglew-dev and reconfigure)";
}
// Message for builds without OSMesa.
inline const char* facetRendererMissingMessage() {
  return "the 'facets' engine needs OSMesa: this qacc was built without it (install libosmesa6-dev "
         "and reconfigure with -DQACC_WITH_OSMESA=ON)";
}

// Makes sure the facet renderer can draw before any work is spent on it: a no-op where the
// renderer is linked in (the tests); in the qacc executable it loads the facets module and
// throws std::runtime_error, naming the module, when that fails
// (tools/engines/facets_module_loader.cpp).
void prepareFacetRenderer();

// What every user of the facet renderer checks first: std::invalid_argument when the build
// has none, std::runtime_error when its module cannot be loaded.
inline void requireFacetRenderer() {
  if (!facetRendererAvailable()) throw std::invalid_argument(facetRendererMissingMessage());
#ifdef QACC_HAVE_OSMESA
  prepareFacetRenderer();
#endif
}

// Renders `mesh` (from tessellateScene) with the scene's camera, lights, materials and image
// size. Throws std::runtime_error when OSMesa cannot create a context.
FacetRenderResult renderFacets(const Scene& scene, const TriangleMesh3& mesh, const FacetRenderOptions& options);

}  // namespace qacc
