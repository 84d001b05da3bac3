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
#include "tests/modeling/piece_of.h"
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

using test::pieceOf;

// The surface vertices of t more than a tenth of the extent's size outside it (each printed).
std::size_t verticesOffThePiece(const PrimitiveTessellation& t, const Eigen::AlignedBox3d& extent,
                                const std::string& what) {
  Eigen::AlignedBox3d near = extent;
  const double pad = 0.1 * extent.sizes().maxCoeff();
  near.min().array() -= pad;
  near.max().array() += pad;
  std::size_t off = 0;
  for (std::size_t k = 0; k < t.surface_triangles; ++k)
    for (int j = 0; j < 3; ++j) {
      const Eigen::Vector3d& x = t.mesh.positions[std::size_t(t.mesh.triangles[k][std::size_t(j)])];
      if (near.contains(x)) continue;
      ++off;
      ADD_FAILURE() << what << ": vertex " << x.transpose() << " off the piece's extent";
    }
  return off;
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
    EXPECT_EQ(verticesOffThePiece(t, sb.box, what), 0u);
    EXPECT_TRUE(inView.surelyInView(sliver, t.mesh, t.surface_triangles)) << what;
    EXPECT_EQ(tessellatePrimitive(empty, o, &s.camera, aspect, &view).mesh.size(), 0u) << what;
  }
}

// At a triangle budget (no view: marching cells count along the region's box), two more pieces
// of bspline_volume_g1 (primitives 40080 and 23746): a piece in a slab the surface crosses at a
// grazing angle, whose facets lay 0.1 world units off the piece (chord error 0.75), and a piece
// whose exact extent is empty but whose marched triangles, inside its region, lay 0.05 off any
// surface. The first is now marched again in its extent until it lies there; the second draws
// nothing.
TEST(PieceBoundary, AtABudgetAPieceInAGrazedSlabLiesWithinItsExtentAndAnEmptyOneDrawsNothing) {
  const Primitive grazed = pieceOf(
      {0.00050856275103873549, 0.00078006811907523977, 9.1483687140811405e-05, -0.0006444719365879968,
       0.00078006811907523977, 1, -0.78865351568144004, -0.90045393689157005,
       9.1483687140811405e-05, -0.78865351568144004, 0.64165309824487116, 0.70861317050657135,
       -0.0006444719365879968, -0.90045393689157005, 0.70861317050657135, 0.81026419796862292},
      {{0, 0.45000000000000007, -0.3600000000000001, -0.40500000000000003},
       {0, 1, 0, -1.2605241172155532},
       {-0.57625887684858479, 0.65088598059275882, 0.061519801940097041, -0.71253519413298549},
       {-0.02466701663336756, -0.053525167063663399, -0.5223682136915393, 0.087687855585505375},
       {0.43962319236764891, 0, 0.062082461935326273, -0.13188695771029468},
       {0.066400310971996737, -0.066400310971996737, -0.42867948833681524, 0.07968037316639609},
       {-0.0010162478590737649, -0.59259775142804516, 0.47489119942969515, 0.53303310192751852}});
  const Primitive empty = pieceOf(
      {-1, 0.0067673064027591653, 0.8082658548918823, -0.90128239857138503,
       0.0067673064027591653, 0.012652603568054987, -0.0095626368706716314, 0.014622232349464803,
       0.8082658548918823, -0.0095626368706716314, -0.62958136350567473, 0.71937435365486901,
       -0.90128239857138503, 0.014622232349464803, 0.71937435365486901, -0.80469430878335246},
      {{0.44999999999999996, 0, -0.35999999999999999, 0.40499999999999997},
       {0, 0, 1, -0.51052411721555324},
       {0, -0.46219818626322279, -0.05653782447482289, -0.37357499928078336},
       {0.1554098420873119, 0.40867099590800909, -0.41944497845895168, 0.50767275419578883},
       {-0.5499758331362814, 0, 0.44131696517743441, -0.49598047382396016}});
  const PrimitiveBounds gb = primitiveBounds(grazed);
  ASSERT_TRUE(gb.bounded && !gb.empty);
  ASSERT_TRUE(primitiveBounds(empty).empty);
  for (int triangles : {64, 128}) {
    TessellationOptions o;
    o.triangles = triangles;
    const PrimitiveTessellation t = tessellatePrimitive(grazed, o);
    ASSERT_GT(t.surface_triangles, 0u) << triangles;
    EXPECT_EQ(t.boundary_defects, 0u) << triangles;
    EXPECT_EQ(verticesOffThePiece(t, gb.box, std::to_string(triangles) + " triangles"), 0u);
    // The piece is 0.22 across: its facets within a thousandth of that of its surface.
    EXPECT_LT(t.max_chord_error, 2e-4) << triangles;
    EXPECT_EQ(tessellatePrimitive(empty, o).mesh.size(), 0u) << triangles;
  }
}
