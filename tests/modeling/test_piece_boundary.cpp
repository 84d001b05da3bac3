// A clipped piece's triangles are a proper piece of its surface (piece_boundary.h): on the
// macropatch scenes, whose cells are small pieces of large quadrics, every piece's vertices
// lie inside its clip planes and its open edges on them — to a pixel error and at a triangle
// budget. A parametric grid clipped in parameter space broke this on 78 of macropatch_g1's
// 144 pieces at ε 2 px (holes inside the piece, vertices up to 0.08 outside a plane), which
// no stitching of shared boundaries can close; tessellation.cpp now refines or marches them.
#include <gtest/gtest.h>

#include <string>

#include "modeling/loader/scene_loader.h"
#include "modeling/tessellation/piece_boundary.h"
#include "modeling/tessellation/screen_error.h"
#include "modeling/tessellation/tessellation.h"
#include "tests/sanitized_build.h"

using namespace qacc;

TEST(PieceBoundary, MacropatchPiecesAreProperPiecesOfTheirSurfaces) {
  for (const char* name : {"macropatch_g0.json", "macropatch_g1.json"}) {
    const Scene s = loadScene(std::string(QACC_SOURCE_DIR) + "/scenes/" + name);
    const ScreenView view(s.camera, s.width, s.height);
    const double aspect = double(s.width) / double(s.height);
    for (double eps : {2.0, 0.5, 0.0}) {
      TessellationOptions o;
      if (eps > 0) o.pixel_error = eps; else o.triangles = 64;
      std::size_t bad = 0, outside = 0, offPlane = 0;
      // Under the sanitizers every seventh piece (about 10 minutes for all of them there).
      const std::size_t stride = kSanitizedBuild ? 7 : 1;
      for (std::size_t i = 0; i < s.primitives.size(); i += stride) {
        const Primitive& p = s.primitives[i];
        ASSERT_FALSE(p.clip.empty());
        const PrimitiveTessellation t = tessellatePrimitive(p, o, &s.camera, aspect, &view);
        const tess::PieceBoundary b = tess::checkPieceBoundary(t.mesh, t.surface_triangles, p.clip);
        EXPECT_EQ(b.defects(), t.boundary_defects);
        if (b.defects()) ++bad;
        outside += b.outside;
        offPlane += b.off_plane_edges;
      }
      EXPECT_EQ(bad, 0u) << name << " eps " << eps << ": " << outside << " vertices outside a plane, " << offPlane
                         << " open edges off the planes";
    }
  }
}

TEST(PieceBoundary, FindsVerticesOutsideAndOpenEdgesOffThePlanes) {
  TriangleMesh3 m;
  m.positions = {{0, 0, 0}, {1, 0, 0}, {0, 1, 0}, {1, 1, 0}};
  m.normals.assign(4, Eigen::Vector3d(0, 0, 1));
  m.triangles = {{0, 1, 2}, {1, 3, 2}};
  // Kept: x <= 1 and y <= 1 — the square's right and top edges are on planes, its left and
  // bottom edges on none.
  const std::vector<HalfSpace> planes = {HalfSpace(Eigen::Vector4d(1, 0, 0, -1)), HalfSpace(Eigen::Vector4d(0, 1, 0, -1))};
  tess::PieceBoundary b = tess::checkPieceBoundary(m, 2, planes);
  EXPECT_EQ(b.outside, 0u);
  EXPECT_EQ(b.off_plane_edges, 2u);
  // x <= 0.5: two vertices outside.
  b = tess::checkPieceBoundary(m, 2, {HalfSpace(Eigen::Vector4d(1, 0, 0, -0.5))});
  EXPECT_EQ(b.outside, 2u);
  // Only the first triangle counted as surface (the second a cap).
  b = tess::checkPieceBoundary(m, 1, planes);
  EXPECT_EQ(b.off_plane_edges, 3u);  // its left and bottom edges, and the diagonal
}
