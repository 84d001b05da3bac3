// A clipped piece's triangles are a proper piece of its surface (piece_boundary.h): on the
// macropatch scenes, whose cells are small pieces of large quadrics, every piece's vertices
// lie inside its clip planes and its open edges on them — to a pixel error and at a triangle
// budget. A parametric grid clipped in parameter space broke this on 78 of macropatch_g1's
// 144 pieces at ε 2 px (holes inside the piece, vertices up to 0.08 outside a plane), which
// no stitching of shared boundaries can close; tessellation.cpp now refines or marches them.
#include <gtest/gtest.h>

#include <array>
#include <string>
#include <vector>

#include "modeling/geometry/primitive_bounds.h"
#include "modeling/loader/scene_loader.h"
#include "modeling/tessellation/piece_boundary.h"
#include "modeling/tessellation/piece_in_view.h"
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

namespace {

Primitive pieceOf(const std::array<double, 16>& q, const std::vector<Eigen::Vector4d>& planes) {
  Primitive p;
  p.quadric = Quadric(Eigen::Map<const Eigen::Matrix4d>(q.data()));
  for (const auto& h : planes) p.clip.emplace_back(h);
  return p;
}

}  // namespace

// Two pieces of bspline_volume_g1 (the scene's primitives 19538 and 35980, their quadrics
// normalised, 17 digits), in the scene's view (640x480), where the stitched facets had a crack
// 0.2 px across and 7 px of open edges:
// - a sliver 6e-4 across in a slab 1e-4 thick, smaller than the marching cells its region's
//   scan chose (0.03): their triangles, cut by the clip planes, made one facet 2 px away
//   from the piece, off the surface, so the piece did not count as in view (piece_in_view.h)
//   and its neighbours were not stitched to it. It is now marched in its exact extent.
// - a piece whose exact extent is empty (no point of its surface inside its clip region), which
//   a parametric grid gave two triangles outside the region. It now draws nothing.
TEST(PieceBoundary, ASliverLiesOnItsSurfaceWithinItsExtentAndAnEmptyPieceDrawsNothing) {
  Scene s;
  s.width = 640;
  s.height = 480;
  s.camera.eye = Eigen::Vector3d(2.4, -3.6, 3.0);
  s.camera.target = Eigen::Vector3d(0, 0, 0);
  s.camera.up = Eigen::Vector3d(0, 0, 1);
  s.camera.fov_y_deg = 30;
  s.camera.near = 0.5;
  s.camera.far = 30;
  const ScreenView view(s.camera, s.width, s.height);
  const double aspect = double(s.width) / double(s.height);
  const Primitive sliver = pieceOf(
      {-0.015684603844719439, 0.0006969077350169687, 0.00096173267432283062, 0.003493342450932465,
       0.0006969077350169687, -1, 0.79989004344625325, 0.89907137044309005,
       0.00096173267432283062, 0.79989004344625325, -0.63294645602939936, -0.7194916461216998,
       0.003493342450932465, 0.89907137044309005, -0.7194916461216998, -0.81018947772890326},
      {{-0.4499999999999999, 0, 0, 0.13499999999999998},
       {0, 0, -1, -0.51052411721555324},
       {-0.52266398006591697, 0.16670594212446554, 0.27575996795848345, 0.10678741138243542},
       {0.53593393764061292, 0.059694258893086966, -0.047755407114469559, -0.21450501429596219},
       {0, -0.47820650999095859, 0.38175220970550783, 0.42977611027641849}});
  const Primitive empty = pieceOf(
      {-0.16376759206972336, 0.028827412842009494, 0.10651785644162449, -6.666399422589166e-05,
       0.028827412842009494, 1, -0.70519231038964769, -0.35537101318837072,
       0.10651785644162449, -0.70519231038964769, 0.46581964174039175, 0.19627008049802974,
       -6.666399422589166e-05, -0.35537101318837072, 0.19627008049802974, 0.12397560120039061},
      {{-0.6090727439500393, 0.44883397904638311, 0.13038197202199103, -0.22122875795673297},
       {-0.11810744126945372, 0.12390972030090633, 0.40254794907538932, -0.072605148471108022},
       {0.23390547349375798, -0.10262292153187502, -0.40623074995626274, 0.022188987330560093},
       {0.027042204277125031, -0.50969425889308706, 0, 0.16102093895106365},
       {0.045253656192447381, -0.4573722512299927, 0.3658978009839941, 0.12363557851126361},
       {0, 0.44505799892358566, -0.24938146661085006, -0.13351739967707571}});

  const PrimitiveBounds sb = primitiveBounds(sliver);
  ASSERT_TRUE(sb.bounded && !sb.empty);
  EXPECT_LT(sb.box.sizes().maxCoeff(), 1e-3);
  EXPECT_TRUE(view.boxOnScreen(sb.box, 0));
  ASSERT_TRUE(primitiveBounds(empty).empty);
  const tess::PieceInView inView(view);
  for (double eps : {2.0, 0.5, 0.0}) {
    TessellationOptions o;
    if (eps > 0) o.pixel_error = eps; else o.triangles = 64;
    const std::string what = eps > 0 ? "eps " + std::to_string(eps) : "64 triangles";
    const PrimitiveTessellation t = tessellatePrimitive(sliver, o, &s.camera, aspect, &view);
    ASSERT_GT(t.surface_triangles, 0u) << what;
    // Within a tenth of its own size of its extent (a facet of a cell larger than the piece
    // lay 0.008 away, 13 times the piece's size).
    Eigen::AlignedBox3d near = sb.box;
    const double pad = 0.1 * sb.box.sizes().maxCoeff();
    near.min().array() -= pad;
    near.max().array() += pad;
    for (std::size_t k = 0; k < t.surface_triangles; ++k)
      for (int j = 0; j < 3; ++j) {
        const Eigen::Vector3d& x = t.mesh.positions[std::size_t(t.mesh.triangles[k][std::size_t(j)])];
        EXPECT_TRUE(near.contains(x)) << what << ": vertex " << x.transpose() << " away from the piece's extent";
      }
    EXPECT_TRUE(inView.surelyInView(sliver, t.mesh, t.surface_triangles)) << what;
    EXPECT_EQ(tessellatePrimitive(empty, o, &s.camera, aspect, &view).mesh.size(), 0u) << what;
  }
}
