// Facets of the true surface (issue 6): objects with an exact surface (algebraic surfaces)
// are tessellated from that surface by marching tetrahedra, not from their quadric pieces.
// Checks: vertices on the true surface (after the object's placement and clip), normals
// along its gradient, the triangle count grows with the level, other objects keep their
// tessellation, the mesh is sized by the object's whole model, so view culling does not change
// it, and the facet image approaches the exact reference as the level rises.
#include <gtest/gtest.h>

#include <cmath>
#include <memory>
#include <string>

#include <nlohmann/json.hpp>

#include "modeling/algebraic/algebraic_surface.h"
#include "modeling/geometry/natural_quadrics.h"
#include "modeling/geometry/placed_exact_surface.h"
#include "modeling/loader/scene_loader.h"
#include "modeling/tessellation/tessellation.h"
#include "raster/metrics/coverage_error.h"
#include "raster/osmesa/osmesa_renderer.h"
#include "raster/metrics/psnr.h"
#include "raster/reference/reference_renderer.h"
#include "tests/sanitized_build.h"

using namespace qacc;
using Eigen::Vector3d;

namespace {

const double kR = 1.0, kr = 0.4;
const char* kTorus = "(x^2+y^2+z^2+R^2-r^2)^2 - 4 R^2 (x^2+y^2)";

Polynomial3 torus() { return Polynomial3::parse(kTorus, {{"R", kR}, {"r", kr}}); }
const Eigen::AlignedBox3d kTorusBox(Vector3d(-1.5, -1.5, -0.5), Vector3d(1.5, 1.5, 0.5));

// Exact distance from p to the torus surface.
double torusDistance(const Vector3d& p) {
  return std::abs(std::hypot(std::hypot(p.x(), p.y()) - kR, p.z()) - kr);
}

Vector3d faceNormal(const ExactSurfaceMesh& m, const std::array<int, 3>& t) {
  const Vector3d& a = m.positions[std::size_t(t[0])];
  return (m.positions[std::size_t(t[1])] - a).cross(m.positions[std::size_t(t[2])] - a);
}

// Degree reduction at level 4: its pieces lie far (~0.1) from the true torus, so a facet
// path that tessellated the pieces would put vertices off the true surface.
std::string torusScene(const std::string& extra, int w = 160, int h = 120) {
  return R"js({"format": "qacc-scene/1", "image": {"width": )js" + std::to_string(w) + R"js(, "height": )js" +
         std::to_string(h) + R"js(},
    "camera": {"type": "perspective", "eye": [0.3, -3.6, 2.6], "target": [0, 0, 0], "up": [0, 0, 1],
               "fov_y_deg": 42, "near": 0.5, "far": 20},
    "objects": [{"type": "algebraic", "poly": "(x^2+y^2+z^2+R^2-r^2)^2 - 4 R^2 (x^2+y^2)",
                 "params": {"R": 1, "r": 0.4}, "box": [[-1.5,-1.5,-0.5],[1.5,1.5,0.5]], "level": 4)js" +
         extra + "}]}";
}

}  // namespace

TEST(ExactFacets, TrianglesLieOnTheTrueSurfaceAndRefineWithTheBudget) {
  const AlgebraicSurface s(torus(), kTorusBox);
  std::size_t previous = 0;
  double previousError = 1e9;
  for (std::size_t budget : {500u, 2000u, 8000u}) {
    const ExactSurfaceMesh m = s.tessellate(budget);
    ASSERT_FALSE(m.triangles.empty());
    EXPECT_GT(m.triangles.size(), previous);
    EXPECT_GT(double(m.triangles.size()), 0.6 * double(budget)) << budget;
    EXPECT_LT(double(m.triangles.size()), 1.6 * double(budget)) << budget;
    ASSERT_EQ(m.normals.size(), m.positions.size());
    for (std::size_t i = 0; i < m.positions.size(); ++i) {
      const Vector3d& p = m.positions[i];
      EXPECT_LT(torusDistance(p), 1e-9) << p.transpose();
      EXPECT_NEAR(m.normals[i].norm(), 1.0, 1e-12);
      EXPECT_GT(m.normals[i].dot(s.polynomial().gradient(p).normalized()), 1 - 1e-12);
    }
    for (const auto& t : m.triangles) {
      const Vector3d n = m.normals[std::size_t(t[0])] + m.normals[std::size_t(t[1])] + m.normals[std::size_t(t[2])];
      EXPECT_GT(faceNormal(m, t).dot(n), 0.0);  // wound counter-clockwise seen from outside
    }
    // The measured distance to the truth shrinks with the budget (chord error ~ 1/budget).
    EXPECT_GT(m.max_error, 0.0);
    EXPECT_LT(m.max_error, previousError);
    EXPECT_LE(m.mean_error, m.max_error);
    previous = m.triangles.size();
    previousError = m.max_error;
  }
}

TEST(ExactFacets, PlacementMapsVerticesAndNormalsAndClips) {
  auto inner = std::make_shared<AlgebraicSurface>(torus(), kTorusBox);
  // Rotated, non-uniformly scaled with a mirror, moved; clipped (local frame) to x <= 0.3.
  const Eigen::Matrix4d M = placement(Vector3d(0.4, -0.2, 1.1), Vector3d(20, -35, 50), Vector3d(1.5, -0.8, 1.2));
  const Eigen::Matrix4d Minv = M.inverse();
  const HalfSpace clip(Eigen::Vector4d(1, 0, 0, -0.3));
  const PlacedExactSurface s(inner, M, {clip});
  const ExactSurfaceMesh m = s.tessellate(4000);
  const ExactSurfaceMesh unplaced = inner->tessellate(4000);
  ASSERT_FALSE(m.triangles.empty());
  EXPECT_LT(m.triangles.size(), unplaced.triangles.size());  // the clip removed a part
  const Eigen::Matrix3d normalMap = Minv.topLeftCorner<3, 3>().transpose();
  int onSurface = 0, onPlane = 0;
  for (std::size_t i = 0; i < m.positions.size(); ++i) {
    const Vector3d local = (Minv * m.positions[i].homogeneous()).head<3>();
    const double g = clip.eval(local);
    EXPECT_LE(g, 1e-12) << "vertex outside the clip region";
    if (std::abs(g) <= 1e-12) {
      ++onPlane;  // a cut point: on the plane, within the chord error of the surface
      EXPECT_LT(torusDistance(local), m.max_error + 1e-12);
      continue;
    }
    ++onSurface;
    EXPECT_LT(torusDistance(local), 1e-9);
    const Vector3d expected = (normalMap * inner->polynomial().gradient(local)).normalized();
    EXPECT_GT(m.normals[i].dot(expected), 1 - 1e-9);
  }
  EXPECT_GT(onSurface, 1000);
  EXPECT_GT(onPlane, 10);
  // The mirror keeps the winding consistent with the normals.
  for (const auto& t : m.triangles) {
    const Vector3d n = m.normals[std::size_t(t[0])] + m.normals[std::size_t(t[1])] + m.normals[std::size_t(t[2])];
    EXPECT_GT(faceNormal(m, t).dot(n), 0.0);
  }
  const double stretch = M.topLeftCorner<3, 3>().jacobiSvd().singularValues()(0);
  EXPECT_NEAR(m.max_error, stretch * unplaced.max_error, 1e-12);
}

TEST(ExactFacets, SceneTessellatesTheTrueSurfaceNotThePieces) {
  const std::string placed = R"js(, "transform": {"scale": [1.5, -0.8, 1.2], "rotate_deg": [10, 0, 30],
                                                  "translate": [0.2, 0.1, -0.3]}}, 
      {"type": "sphere", "center": [2.5, 0, 0], "radius": 0.5)js";
  const Scene scene = parseScene(torusScene(placed), "exact.json", ".");
  ASSERT_EQ(scene.objects.size(), 2u);
  ASSERT_EQ(scene.objects[0].exact_surface, 0);
  const Eigen::Matrix4d Minv =
      placement(Vector3d(0.2, 0.1, -0.3), Vector3d(10, 0, 30), Vector3d(1.5, -0.8, 1.2)).inverse();
  // The sphere keeps its own tessellation.
  const Primitive& sphere = scene.primitives.back();
  ASSERT_EQ(sphere.object, 1);
  std::size_t previous = 0;
  for (int level : {8, 32}) {
    if (kSanitizedBuild && level == 32) continue;  // level 8 only (tests/sanitized_build.h)
    TessellationOptions to;
    to.triangles = level;
    TessellationReport rep;
    const TriangleMesh3 mesh = tessellateScene(scene, to, &rep);
    EXPECT_EQ(rep.exact_surfaces, 1u);
    EXPECT_EQ(rep.primitives, 1u);  // the sphere; the torus pieces are not tessellated
    EXPECT_GT(rep.exact_grid, 0);
    std::size_t torusTriangles = 0, sphereTriangles = 0;
    for (std::size_t t = 0; t < mesh.size(); ++t) {
      if (mesh.object[t] == 1) {
        ++sphereTriangles;
        continue;
      }
      ASSERT_EQ(mesh.object[t], 0);
      ++torusTriangles;
      for (int v : mesh.triangles[t]) {
        const Vector3d local = (Minv * mesh.positions[std::size_t(v)].homogeneous()).head<3>();
        ASSERT_LT(torusDistance(local), 1e-9) << "a facet vertex off the true surface";
      }
    }
    EXPECT_EQ(rep.exact_triangles, torusTriangles);
    EXPECT_EQ(sphereTriangles, tessellatePrimitive(sphere, to, &scene.camera, 4.0 / 3.0).mesh.size());
    // The budget is `level` triangles per cell of the object's model (6 x 4^3 Kuhn cells).
    ASSERT_EQ(scene.objects[0].model_cells, 384u);
    const double budget = double(level) * double(scene.objects[0].model_cells);
    EXPECT_GT(double(torusTriangles), 0.6 * budget);
    EXPECT_LT(double(torusTriangles), 1.6 * budget);
    EXPECT_GT(torusTriangles, 3 * previous);
    previous = torusTriangles;
  }
  // "reference": "pieces" has no exact surface: its pieces are tessellated as before.
  const Scene pieces = parseScene(torusScene(R"js(, "reference": "pieces")js"), "pieces.json", ".");
  TessellationReport rep;
  tessellateScene(pieces, TessellationOptions{8}, &rep);  // 8 triangles a piece: which path, not how fine
  EXPECT_EQ(rep.exact_surfaces, 0u);
  EXPECT_EQ(rep.primitives, pieces.primitives.size());
}

TEST(ExactFacets, MeshDoesNotDependOnViewCulling) {
  // A zoomed view on part of the torus: culling keeps few of its pieces, and the mesh of its
  // true surface is the one of the unculled scene, triangle for triangle.
  nlohmann::json doc = nlohmann::json::parse(torusScene(""));
  doc["camera"]["fov_y_deg"] = 6;
  doc["camera"]["target"] = {1.0, 0.0, 0.2};
  const Scene culled = parseScene(doc.dump(), "exact.json", ".");
  const Scene unculled = parseScene(doc.dump(), "exact.json", ".", Limits{}, ViewCulling{false, 0, 0});
  ASSERT_GT(culled.primitives.size(), 0u);
  ASSERT_LT(2 * culled.primitives.size(), unculled.primitives.size());
  for (const TessellationOptions& to : {TessellationOptions{6}, TessellationOptions{32}}) {
    if (kSanitizedBuild && to.triangles == 32) continue;  // level 6 only (tests/sanitized_build.h)
    TessellationReport a, b;
    const TriangleMesh3 ma = tessellateScene(culled, to, &a), mb = tessellateScene(unculled, to, &b);
    EXPECT_EQ(a.exact_triangles, b.exact_triangles);
    ASSERT_EQ(ma.size(), mb.size());
    EXPECT_EQ(ma.positions, mb.positions);
    EXPECT_EQ(ma.triangles, mb.triangles);
  }
  // By pixel error too (the budget quadrupled from 64 per cell until the bound holds).
  TessellationOptions pe;
  pe.pixel_error = kSanitizedBuild ? 4.0 : 1.0;  // fewer budget steps under the sanitizers (tests/sanitized_build.h)
  TessellationReport a, b;
  EXPECT_EQ(tessellateScene(culled, pe, &a).positions, tessellateScene(unculled, pe, &b).positions);
  EXPECT_EQ(a.exact_grid, b.exact_grid);
}

TEST(ExactFacets, MeshDoesNotDependOnViewCullingThatRemovesEveryPiece) {
  // The view aims beside the torus, at a sphere: culling removes every piece of the torus,
  // and the facets still draw its true surface (whose chords may reach a view its pieces do
  // not), the same triangles as unculled, before the sphere's as in the unculled scene.
  nlohmann::json doc = nlohmann::json::parse(torusScene(R"js(}, {"type": "sphere", "center": [4, 0, 0], "radius": 0.5)js"));
  doc["camera"]["target"] = {4.0, 0.0, 0.0};
  doc["camera"]["fov_y_deg"] = 10;
  const Scene culled = parseScene(doc.dump(), "exact.json", ".");
  const Scene unculled = parseScene(doc.dump(), "exact.json", ".", Limits{}, ViewCulling{false, 0, 0});
  ASSERT_EQ(culled.objects[0].count, 0u);
  ASSERT_GT(unculled.objects[0].count, 0u);
  ASSERT_EQ(culled.objects[1].count, 1u);
  TessellationReport a, b;
  const TriangleMesh3 ma = tessellateScene(culled, TessellationOptions{6}, &a),
                      mb = tessellateScene(unculled, TessellationOptions{6}, &b);
  EXPECT_EQ(a.exact_surfaces, 1u);
  EXPECT_EQ(a.exact_triangles, b.exact_triangles);
  EXPECT_EQ(ma.positions, mb.positions);
  EXPECT_EQ(ma.triangles, mb.triangles);
  EXPECT_EQ(ma.object, mb.object);
}

TEST(ExactFacets, ChordErrorBoundRefinesTheTrueSurface) {
  const Scene scene = parseScene(torusScene(""), "exact.json", ".");
  TessellationOptions to;
  to.chord_error = 2e-3;
  TessellationReport rep;
  const TriangleMesh3 mesh = tessellateScene(scene, to, &rep);
  EXPECT_EQ(rep.exact_surfaces, 1u);
  EXPECT_LE(rep.max_chord_error, 2e-3);
  EXPECT_GT(rep.max_chord_error, 2e-3 / 16);  // one budget step (x4) coarser would miss the bound
}

#ifdef QACC_HAVE_OSMESA
TEST(ExactFacets, FacetImageApproachesTheTruthAsTheLevelRises) {
  if (!facetRendererAvailable()) GTEST_SKIP() << facetRendererMissingMessage();
  const Scene scene = parseScene(torusScene(""), "exact.json", ".");
  const FrameBuffer truth = renderReference(scene, 2);
  double previousCoverage = 1e18, previousPsnr = 0;
  for (int level : {2, 8, 32}) {
    TessellationOptions to;
    to.triangles = level;
    const FacetRenderResult r = renderFacets(scene, tessellateScene(scene, to), FacetRenderOptions());
    const CoverageError ce = coverageError(truth, r.fb);
    const double coverage = double(ce.errors());
    const double p = psnr(truth, r.fb);
    EXPECT_LT(coverage, previousCoverage) << level;
    EXPECT_GT(p, previousPsnr) << level;
    previousCoverage = coverage;
    previousPsnr = p;
  }
  // 32 triangles per piece: silhouettes within a pixel or so of the truth.
  EXPECT_LT(previousCoverage, 0.01 * double(coverageError(truth, truth).reference_covered));
}
TEST(ExactFacets, AnObjectWithoutPiecesIsDrawnAsWithThem) {
  // An object whose pieces view culling all removed is drawn by its true surface, with its own
  // object id (the id pass has no primitive for it): the image of the torus without its pieces
  // is the image with them.
  if (!facetRendererAvailable()) GTEST_SKIP() << facetRendererMissingMessage();
  const Scene scene = parseScene(torusScene("", 64, 48), "exact.json", ".");
  Scene piecesRemoved = scene;
  piecesRemoved.primitives.clear();
  piecesRemoved.objects[0].count = 0;
  TessellationOptions to;
  to.triangles = 6;
  const FrameBuffer a = renderFacets(scene, tessellateScene(scene, to), FacetRenderOptions()).fb;
  const FrameBuffer b = renderFacets(piecesRemoved, tessellateScene(piecesRemoved, to), FacetRenderOptions()).fb;
  std::size_t drawn = 0;
  for (int o : a.object) drawn += o == 0;
  EXPECT_GT(drawn, 500u);
  EXPECT_EQ(a.object, b.object);
  EXPECT_EQ(a.color.data, b.color.data);
  EXPECT_EQ(a.depth, b.depth);
}
#endif  // QACC_HAVE_OSMESA
