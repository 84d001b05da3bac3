// The facets engine's box pruning of csg products (raster/osmesa/facet_csg_draw.h) never
// drops a product or a complemented leaf that would draw a pixel, and the boxes it gives
// OpenCSG never scissor one away: on a scene whose operands are disjoint, overlapping and
// touching (shared faces), the pruned and the unpruned images are identical, colour, depth
// and ids.
#include <gtest/gtest.h>

#include "modeling/loader/scene_loader.h"
#include "modeling/tessellation/tessellation.h"
#include "raster/osmesa/osmesa_renderer.h"
#ifdef QACC_HAVE_OPENCSG
#include "raster/osmesa/facet_csg_draw.h"
#endif

using namespace qacc;

#ifdef QACC_HAVE_OPENCSG
namespace {

// Five csg objects: two spheres apart intersected (empty: the product is skipped); a
// sphere minus a far sphere (left out) and minus a cylinder through it; a cylinder minus a
// narrower one standing on its top face (boxes touch: kept, coincident caps); a sphere
// intersected with a cylinder tangent to it (boxes overlap, the solids touch along a line);
// a cylinder minus a sphere biting into its side, partly beyond the image border (its box
// clamped to the view).
const char* kPruningScene = R"({"format": "qacc-scene/1", "name": "csg_pruning",
 "image": {"width": 240, "height": 180},
 "camera": {"type": "perspective", "eye": [0.8, -4.2, 2.6], "target": [0.2, 0, 0.5], "up": [0, 0, 1],
            "fov_y_deg": 45, "near": 1, "far": 20},
 "lights": [{"type": "directional", "direction": [-1, 1, -1], "color": [1, 1, 1]},
            {"type": "ambient", "color": [0.2, 0.2, 0.2]}],
 "materials": {"a": {"color": [0.8, 0.5, 0.3]}, "b": {"color": [0.3, 0.6, 0.9]}},
 "objects": [
  {"type": "csg", "op": "intersection", "material": "a", "children": [
     {"type": "sphere", "center": [-2.5, 0, 1.5], "radius": 0.4, "solid": true},
     {"type": "sphere", "center": [-1.2, 0, 1.5], "radius": 0.4, "solid": true}]},
  {"type": "csg", "op": "difference", "material": "a", "children": [
     {"type": "sphere", "center": [-1.5, 0, 0], "radius": 0.7, "solid": true},
     {"type": "sphere", "center": [2.5, 2, 2], "radius": 0.3, "solid": true, "material": "b"},
     {"type": "cylinder", "base": [-1.5, -1, 0], "top": [-1.5, 1, 0], "radius": 0.3, "solid": true,
      "material": "b"}]},
  {"type": "csg", "op": "difference", "material": "a", "children": [
     {"type": "cylinder", "base": [0.5, 0, -0.5], "top": [0.5, 0, 0.5], "radius": 0.5, "solid": true},
     {"type": "cylinder", "base": [0.5, 0, 0.5], "top": [0.5, 0, 1.5], "radius": 0.3, "solid": true,
      "material": "b"},
     {"type": "cylinder", "base": [0.5, -1, 0.2], "top": [0.5, 1, 0.2], "radius": 0.2, "solid": true,
      "material": "b"}]},
  {"type": "csg", "op": "intersection", "material": "b", "children": [
     {"type": "sphere", "center": [2, 0, 0], "radius": 0.5, "solid": true},
     {"type": "cylinder", "base": [1.5, 0, 0.7], "top": [2.5, 0, 0.7], "radius": 0.2, "solid": true}]},
  {"type": "csg", "op": "difference", "material": "a", "children": [
     {"type": "cylinder", "base": [2, 0, 1.2], "top": [2, 0, 2.2], "radius": 0.4, "solid": true},
     {"type": "sphere", "center": [2.3, -0.25, 1.7], "radius": 0.12, "solid": true, "material": "b"}]}
 ]})";

}  // namespace

TEST(FacetCsgPruning, PrunedAndUnprunedImagesAreIdentical) {
  if (!facetRendererAvailable()) GTEST_SKIP() << facetRendererMissingMessage();
  const Scene s = parseScene(kPruningScene, "pruning.json", ".");
  TessellationOptions to;
  to.triangles = 512;
  const TriangleMesh3 mesh = tessellateScene(s, to);
  // The scene exercises every case: a product skipped, a complemented leaf left out, and
  // touching and overlapping boxes kept.
  const FacetCsgPruning p = FacetCsgDraw(s, mesh).pruning();
  EXPECT_EQ(p.products, 5u);
  EXPECT_EQ(p.skipped, 1u);
  EXPECT_EQ(p.literals_dropped, 1u);
  EXPECT_EQ(FacetCsgDraw(s, mesh, false).pruning().skipped, 0u);

  FacetRenderOptions on, off;
  off.csg_box_pruning = false;
  const FrameBuffer a = renderFacets(s, mesh, on).fb, b = renderFacets(s, mesh, off).fb;
  long long covered = 0, differ = 0;
  for (std::size_t i = 0; i < a.pixels(); ++i) {
    covered += a.object[i] >= 0;
    differ += a.primitive[i] != b.primitive[i] || a.depth[i] != b.depth[i] ||
              a.color.data[3 * i] != b.color.data[3 * i] || a.color.data[3 * i + 1] != b.color.data[3 * i + 1] ||
              a.color.data[3 * i + 2] != b.color.data[3 * i + 2];
  }
  EXPECT_GT(covered, 2000);  // the scene is on screen
  EXPECT_EQ(differ, 0);
}
#endif  // QACC_HAVE_OPENCSG
