// No cracks along shared boundaries when the facets are drawn: the macropatch, B-spline and
// degree-reduction scenes tessellated to a pixel error (tessellation.h) and rendered by
// OSMesa show no pinhole and, away from the reference's outline and occluding contours, no
// background where the reference shows the surface and, on the closed surfaces, no back face
// (render_checks.h, cracksAwayFromContours). Near those contours a tessellation shows both
// without any crack: a chord leaves a pixel centre the true surface covers by a sliver, and
// the far side's chords reach past the near side's. Counted everywhere (insideViews), the back
// faces are 14 / 1 on macropatch_g0, 7 / 0 on macropatch_g1 and 40 / 3 on the torus's pieces
// at 2 / 0.5 px, every one of them 1 px from the background; the background pixels enclosed by
// the torus's facets are its own hole.
#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>
#include <ostream>
#include <string>
#include <vector>

#include "modeling/loader/scene_loader.h"
#include "modeling/tessellation/tessellation.h"
#include "raster/osmesa/osmesa_renderer.h"
#include "raster/reference/reference_renderer.h"
#include "tests/sanitized_build.h"
#include "tests/tools/render_checks.h"

using namespace qacc;

#ifdef QACC_HAVE_OSMESA
namespace {

struct PinholeCase {
  const char* scene;
  bool closed;
};
void PrintTo(const PinholeCase& c, std::ostream* os) { *os << c.scene; }

class SharedBoundaryPinholes : public ::testing::TestWithParam<PinholeCase> {};

// The pixels near the reference's contours, where a tessellation to eps px may show the
// background or back faces without a crack: within eps + 2 px of them; an occluding contour
// is a depth step of more than 8 pixels' worth between neighbours.
std::vector<char> excused(const Scene& s, const FrameBuffer& truth, double eps) {
  return nearTruthContours(s, truth, int(std::ceil(eps)) + 2, 8.0);
}

}  // namespace

TEST_P(SharedBoundaryPinholes, FacetsOfPiecesHaveNoCracks) {
  if (!facetRendererAvailable()) GTEST_SKIP() << facetRendererMissingMessage();
  const PinholeCase& c = GetParam();
  if (kSanitizedBuild && std::string(c.scene) != "macropatch_g0.json")
    GTEST_SKIP() << c.scene << ": left to the Release suite (CI's budget; the same code paths as macropatch_g0)";
  Scene s = loadScene(std::string(QACC_SOURCE_DIR) + "/scenes/" + c.scene);
  // The degree-reduction pieces themselves, not the true surface.
  for (auto& o : s.objects) o.exact_surface = -1;
  s.exact_surfaces.clear();
  const FrameBuffer truth = renderReference(s, 0);
  for (double eps : kSanitizedBuild ? std::vector<double>{2.0} : std::vector<double>{2.0, 0.5}) {
    TessellationOptions to;
    to.pixel_error = eps;
    const FacetRenderResult r = renderFacets(s, tessellateScene(s, to), FacetRenderOptions());
    const int pin = pinholes(r.fb), enclosed = enclosedBackgroundPixels(r.fb, &truth);
    const int cracks = cracksAwayFromContours(s, truth, r.fb, excused(s, truth, eps), c.closed);
    std::printf("%s eps %g: %d pinholes, %d enclosed background pixels the reference covers, %d cracks away from "
                "its contours",
                c.scene, eps, pin, enclosed, cracks);
    if (c.closed) std::printf(", %d back faces seen in all", insideViews(s, r.fb));
    EXPECT_EQ(pin, 0) << c.scene << " eps " << eps;
    EXPECT_EQ(cracks, 0) << c.scene << " eps " << eps;
    std::printf("\n");
  }
}

// The checks can fail: a surface with a piece left out shows the background and the inside.
TEST(SharedBoundaryPinholesCheck, APieceLeftOutIsACrack) {
  if (!facetRendererAvailable()) GTEST_SKIP() << facetRendererMissingMessage();
  if (kSanitizedBuild) GTEST_SKIP() << "left to the Release suite (CI's budget; macropatch_g0's case runs the same checks)";
  Scene s = loadScene(std::string(QACC_SOURCE_DIR) + "/scenes/macropatch_g0.json");
  const FrameBuffer truth = renderReference(s, 0);
  TessellationOptions to;
  to.pixel_error = 2;
  const TriangleMesh3 mesh = tessellateScene(s, to);
  // Leave out the triangles of the primitive that covers the image centre.
  const int centre = truth.primitive[std::size_t(truth.height / 2) * truth.width + truth.width / 2];
  ASSERT_GE(centre, 0);
  TriangleMesh3 holed = mesh;
  holed.triangles.clear();
  holed.object.clear();
  holed.material.clear();
  holed.primitive.clear();
  for (std::size_t t = 0; t < mesh.size(); ++t) {
    if (mesh.primitive[t] == centre) continue;
    holed.triangles.push_back(mesh.triangles[t]);
    holed.object.push_back(mesh.object[t]);
    holed.material.push_back(mesh.material[t]);
    holed.primitive.push_back(mesh.primitive[t]);
  }
  ASSERT_LT(holed.size(), mesh.size());
  const std::vector<char> near = excused(s, truth, 2);
  EXPECT_EQ(cracksAwayFromContours(s, truth, renderFacets(s, mesh, FacetRenderOptions()).fb, near, true), 0);
  const FacetRenderResult r = renderFacets(s, holed, FacetRenderOptions());
  EXPECT_GT(cracksAwayFromContours(s, truth, r.fb, near, true), 20);
}

INSTANTIATE_TEST_SUITE_P(Scenes, SharedBoundaryPinholes,
                         ::testing::Values(PinholeCase{"macropatch_g0.json", true},
                                           PinholeCase{"macropatch_g1.json", true},
                                           PinholeCase{"bspline_g1.json", false},
                                           PinholeCase{"torus.json", true}));
// Disabled for its cost alone: 150 s in Release (most of it loading and tessellating the
// volume's 107 k cells), more than CI's margin. It passes since the stitching's degenerate
// cases were handled (0 cracks at 2 and 0.5 px; 3 / 7 before; docs/COMPARE.md "Cracks in
// the drawn facets"). Run it with --gtest_also_run_disabled_tests.
INSTANTIATE_TEST_SUITE_P(DISABLED_Volume, SharedBoundaryPinholes,
                         ::testing::Values(PinholeCase{"bspline_volume_g1.json", true}));
#endif  // QACC_HAVE_OSMESA
