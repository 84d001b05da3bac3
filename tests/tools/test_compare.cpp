// Facets through OSMesa against the exact reference, and `qacc compare` end to end.
#include <gtest/gtest.h>

#include <nlohmann/json.hpp>

#include <cstdio>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <stdexcept>
#include <string>

#include "modeling/geometry/natural_quadrics.h"
#include "modeling/tessellation/tessellation.h"
#include "raster/metrics/coverage_error.h"
#include "raster/metrics/depth_error.h"
#include "raster/osmesa/osmesa_renderer.h"
#include "raster/metrics/psnr.h"
#include "raster/reference/reference_renderer.h"
#include "raster/metrics/silhouette_distance.h"
#include "tests/tools/command_run.h"
#include "tools/engines/image_size.h"

using namespace qacc;

namespace {

[[maybe_unused]] Scene sphereScene(int w, int h) {
  Scene s;
  s.name = "sphere";
  s.width = w;
  s.height = h;
  s.camera.eye = Eigen::Vector3d(0.3, 0.5, 6);
  s.camera.target = Eigen::Vector3d(0, 0, 0);
  s.camera.fov_y_deg = 35;
  s.camera.near = 1;
  s.camera.far = 20;
  s.lights = Scene::defaultLights(s.camera);
  s.materials = {Material()};
  s.primitives = {makeSphere(Eigen::Vector3d(0.2, -0.1, 0), 1.3)};
  SceneObject o;
  o.type = "sphere";
  o.count = 1;
  s.objects = {o};
  return s;
}

// Runs `qacc compare SCENE ARGS --out <build>/DIR`; returns the exit status and the output.
int runCompareCommand(const std::string& scene, const std::string& args, const std::string& dir, std::string& text) {
  namespace fs = std::filesystem;
  const fs::path out = fs::path(QACC_BINARY_DIR) / dir;
  fs::remove_all(out);
  const CommandRun r = runCommand(qaccCommand("compare " + std::string(QACC_SOURCE_DIR) + "/scenes/" + scene + " " +
                                              args + " --out " + out.string() + " 2>&1"));
  text = r.out;
  return r.status;
}

}  // namespace

#ifdef QACC_HAVE_OSMESA
TEST(OsmesaFacets, HighLevelSphereMatchesReferenceSilhouette) {
  if (!facetRendererAvailable()) GTEST_SKIP() << facetRendererMissingMessage();
  const Scene s = sphereScene(240, 180);
  const FrameBuffer ref = renderReference(s, 2);
  TessellationOptions to;
  to.triangles = 8192;
  TessellationReport rep;
  const TriangleMesh3 mesh = tessellateScene(s, to, &rep);
  FacetRenderOptions ro;
  const FacetRenderResult r = renderFacets(s, mesh, ro);
  EXPECT_NE(r.gl_renderer.find("llvmpipe"), std::string::npos) << r.gl_renderer;
  EXPECT_FALSE(r.gl_version.empty());
  const SilhouetteDistance sd = silhouetteDistance(ref, r.fb, 1.0);
  EXPECT_GT(sd.reference_boundary, 300u);
  EXPECT_GE(sd.within_tolerance, 0.995);
  EXPECT_LE(sd.hausdorff, 1.5);
  const CoverageError ce = coverageError(ref, r.fb);
  EXPECT_LT(double(ce.pinholes + ce.spurious), 0.005 * double(ce.reference_covered));
  // Depth through the 24-bit buffer and the same projection: the facets lie inside the
  // sphere by at most the chord error, so along the mostly head-on view rays the mean depth
  // error is of that order (grazing pixels near the silhouette stretch it).
  const DepthError de = depthError(ref, r.fb, s.camera);
  EXPECT_GT(de.pixels, 10000u);
  EXPECT_GT(rep.max_chord_error, 0.0);
  EXPECT_LT(de.mean_view, 3.0 * rep.max_chord_error) << "max " << de.max_view << ", chord " << rep.max_chord_error;
  // Same shading function: Gouraud on a fine mesh is close to the per-pixel reference.
  EXPECT_GT(psnr(ref, r.fb), 30.0);
  // Per-pixel lighting is closer still (or says why it is unavailable).
  ro.shading = FacetShading::PerPixel;
  const FacetRenderResult p = renderFacets(s, mesh, ro);
  if (p.shading_used == FacetShading::PerPixel) {
    EXPECT_GT(psnr(ref, p.fb), 35.0);
  } else {
    EXPECT_FALSE(p.note.empty());
  }
}

TEST(OsmesaFacets, CoarseSphereShowsChordError) {
  if (!facetRendererAvailable()) GTEST_SKIP() << facetRendererMissingMessage();
  // An 8-triangle "sphere" is an octahedron-like solid: far fewer pixels than the sphere.
  const Scene s = sphereScene(160, 120);
  const FrameBuffer ref = renderReference(s, 2);
  TessellationOptions to;
  to.triangles = 8;
  const FacetRenderResult r = renderFacets(s, tessellateScene(s, to), FacetRenderOptions());
  const CoverageError ce = coverageError(ref, r.fb);
  EXPECT_GT(ce.pinholes, ce.reference_covered / 10);
  EXPECT_GT(silhouetteDistance(ref, r.fb).hausdorff, 3.0);
}

#endif  // QACC_HAVE_OSMESA

TEST(CompareCommand, GalleryWritesFilesAndCrossoverTable) {
  if (!facetRendererAvailable()) GTEST_SKIP() << facetRendererMissingMessage();
  namespace fs = std::filesystem;
  const fs::path out = fs::path(QACC_BINARY_DIR) / "test_compare_out";
  std::string text;
  ASSERT_EQ(runCompareCommand("gallery.json", "--levels 8,64 --width 200 --height 150 --threads 2", "test_compare_out", text), 0)
      << text;
  for (const char* f : {"compare.json", "compare.csv", "side_by_side.png", "error_vs_triangles.svg",
                        "error_vs_cycles.svg"})
    EXPECT_TRUE(fs::exists(out / f)) << f;
  EXPECT_NE(text.find("equal error"), std::string::npos);
  EXPECT_NE(text.find("equal cost"), std::string::npos);
  std::ifstream jf(out / "compare.json");
  const nlohmann::json j = nlohmann::json::parse(jf);
  ASSERT_EQ(j["rows"].size(), 3u);  // hw + 2 levels
  EXPECT_EQ(j["rows"][0]["engine"], "hw");
  EXPECT_GT(j["rows"][0]["cycles"].get<long long>(), 0);
  EXPECT_LT(j["rows"][1]["primitives"].get<long long>(), j["rows"][2]["primitives"].get<long long>());
  EXPECT_GT(j["rows"][2]["cycles"].get<long long>(), 0);
  ASSERT_EQ(j["equal_error"].size(), 6u);
  // Equal error is interpolated between measured settings (or at most one step beyond):
  // the settings it names are among the rows.
  for (const auto& e : j["equal_error"]) {
    ASSERT_TRUE(e.contains("reached"));
    ASSERT_TRUE(e.contains("status"));
    if (e["status"] != "not_reached")
      for (const auto& s : e["between"]) EXPECT_TRUE(s == "level 8" || s == "level 64") << s;
    else
      EXPECT_EQ(e["finest_setting"], "level 64");
  }
  EXPECT_TRUE(j["equal_cost"].contains("draw_ms"));  // the draw alone, context and upload apart
  EXPECT_GT(j["rows"][1]["context_ms"].get<double>(), 0);
  EXPECT_TRUE(fs::exists(out / "side_by_side.json"));
  EXPECT_TRUE(fs::exists(out / "panels" / "facets_luma_error.png"));
  EXPECT_TRUE(j["equal_cost"].contains("primitives"));
  EXPECT_NE(j["gl_renderer"].get<std::string>().find("llvmpipe"), std::string::npos);
  // The accelerator's own quadrics beat the coarsest facets on PSNR.
  EXPECT_GT(j["rows"][0]["psnr_db"].get<double>(), j["rows"][1]["psnr_db"].get<double>());
  std::ifstream cf(out / "compare.csv");
  int lines = 0;
  for (std::string l; std::getline(cf, l);) ++lines;
  EXPECT_EQ(lines, 5);  // the description line, the header, hw and 2 levels
}

TEST(CompareCommand, RefusesAnImageOverTheSizeLimit) {
  // The same size check as render and batch (tools/engines/image_size.h), limit included.
  std::string text;
  const int status = runCompareCommand("gallery.json", "--levels 8 --width 100000 --height 240", "test_compare_size_out", text);
  EXPECT_EQ(status, 1) << text;
  EXPECT_NE(text.find("qacc: error: image size 100000x240 is over the limit"), std::string::npos) << text;
}

TEST(ImageSize, OneCheckForEveryCommand) {
  EXPECT_NO_THROW(checkImageSize(0, 0));
  EXPECT_NO_THROW(checkImageSize(kMaxImageSide, 4096));
  EXPECT_THROW(checkImageSize(320, 0), std::invalid_argument);
  EXPECT_THROW(checkImageSize(-320, -240), std::invalid_argument);
  EXPECT_THROW(checkImageSize(kMaxImageSide + 1, 16), std::invalid_argument);
  EXPECT_THROW(checkImageSize(kMaxImageSide, kMaxImageSide), std::invalid_argument);  // over kMaxImagePixels
  Scene s;
  s.width = 64;
  s.height = 48;
  applyImageSize(s, 0, 0);
  EXPECT_EQ(s.width, 64);
  applyImageSize(s, 320, 240);
  EXPECT_EQ(s.width, 320);
  EXPECT_EQ(s.height, 240);
}

TEST(CompareCommand, FacetsEngineRefusesClearlyWithoutOsmesa) {
  if (facetRendererAvailable()) GTEST_SKIP() << "OSMesa is built in";
  const CommandRun r = runCommand(
      qaccCommand("render " + std::string(QACC_SOURCE_DIR) + "/scenes/gallery.json -o /dev/null --engine facets 2>&1"));
  EXPECT_NE(r.status, 0);
  EXPECT_NE(r.out.find("OSMesa"), std::string::npos) << r.out;
}

TEST(CompareCommand, AlgebraicSceneFacetsAreTrianglesOfTheTrueSurface) {
  // The torus: reference = the true surface, hw = its quadric pieces, facets = marching
  // tetrahedra of the true surface, whose distance to it is reported and shrinks.
  if (!facetRendererAvailable()) GTEST_SKIP() << facetRendererMissingMessage();
  namespace fs = std::filesystem;
  const fs::path out = fs::path(QACC_BINARY_DIR) / "test_compare_torus_out";
  std::string text;
  ASSERT_EQ(runCompareCommand("torus.json", "--levels 2,16 --width 160 --height 120 --threads 2 --no-facet-cycles",
                              "test_compare_torus_out", text),
            0)
      << text;
  EXPECT_NE(text.find("marching tetrahedra of the true surface"), std::string::npos) << text;
  std::ifstream jf(out / "compare.json");
  const nlohmann::json j = nlohmann::json::parse(jf);
  ASSERT_EQ(j["rows"].size(), 3u);
  const auto& coarse = j["rows"][1];
  const auto& fine = j["rows"][2];
  // The true surface's budget: triangles per cell of the torus's level-8 Kuhn mesh (6 x 8^3),
  // whatever view culling kept (modeling/tessellation/exact_facets.h).
  const double cells = 6.0 * 8 * 8 * 8;
  EXPECT_EQ(j["format"], "qacc-compare/3");
  for (const auto* r : {&coarse, &fine}) {
    EXPECT_GT((*r)["exact_surface_grid"].get<int>(), 0);
    // One true surface: no shared plane between pieces, nothing left unstitched.
    EXPECT_EQ((*r)["unstitched_shared_planes"].get<int>(), 0);
    EXPECT_EQ((*r)["unstitched_pieces"].get<int>(), 0);
    const double budget = (*r)["level"].get<double>() * cells;
    EXPECT_GT((*r)["primitives"].get<double>(), 0.6 * budget);
    EXPECT_LT((*r)["primitives"].get<double>(), 1.6 * budget);
  }
  EXPECT_LT(fine["chord_error"].get<double>(), coarse["chord_error"].get<double>());
  EXPECT_LT(fine["coverage_px"].get<double>(), coarse["coverage_px"].get<double>());
  EXPECT_GT(fine["psnr_db"].get<double>(), coarse["psnr_db"].get<double>());
}
