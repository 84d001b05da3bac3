// Tessellation to a screen-space error (tessellation.h, `pixel_error`): the achieved
// projected chord error of every natural quadric, measured here independently of the
// tessellator (a denser barycentric grid, each sample projected with the scene's window
// matrix together with its closest surface point), is at most ε; the triangle count falls
// as ε grows; the options are exclusive.
#include <gtest/gtest.h>

#include <cmath>
#include <stdexcept>
#include <string>
#include <vector>

#include "modeling/geometry/natural_quadrics.h"
#include "modeling/scene/scene.h"
#include "modeling/tessellation/screen_error.h"
#include "modeling/tessellation/tessellation.h"
#include "tests/sanitized_build.h"

using namespace qacc;
using Eigen::Vector3d;

namespace {

struct Case {
  std::string name;
  Primitive prim;
};

std::vector<Case> naturalQuadrics() {
  std::vector<Case> c;
  c.push_back({"sphere", makeSphere(Vector3d(0.3, -0.2, 0), 1.2)});
  c.push_back({"ellipsoid", makeEllipsoid(Vector3d(-0.5, 0.4, 0.2), Vector3d(1.4, 0.6, 0.9))});
  c.push_back({"cylinder", makeCylinder(Vector3d(-1, -1, 0), Vector3d(1, 1, 0.5), 0.6)});
  c.push_back({"cone", makeCone(Vector3d(0, 1.2, 0), Vector3d(0.3, -1, 0.2), 0.9)});
  c.push_back({"paraboloid", makeParaboloid(0.8, 0.6, 1.5)});
  c.push_back({"hyperboloid1", makeHyperboloid1(Vector3d(0.7, 0.5, 0.6), 1.5)});
  c.push_back({"hyperboloid2", makeHyperboloid2(Vector3d(0.5, 0.6, 0.4), 1.5)});
  Primitive clipped = makeSphere(Vector3d::Zero(), 1.3);
  clipped.clip = {HalfSpace(Eigen::Vector4d(1, 0.2, 0, -0.3)), HalfSpace(Eigen::Vector4d(0, 1, 0.3, -0.2))};
  clipped.solid = true;
  c.push_back({"clipped sphere", clipped});
  Primitive clippedCyl = makeCylinder(Vector3d(0, -1.5, 0), Vector3d(0, 1.5, 0), 0.8);
  clippedCyl.clip.push_back(HalfSpace(Eigen::Vector4d(0.6, 0.8, 0.1, -0.2)));
  clippedCyl.solid = true;
  c.push_back({"clipped cylinder", clippedCyl});
  return c;
}

Scene sceneOf(const Primitive& p, Camera::Type type) {
  Scene s;
  s.width = 320;
  s.height = 240;
  s.camera.type = type;
  s.camera.eye = Vector3d(1.5, 2.0, 6.0);
  s.camera.target = Vector3d(0, 0, 0);
  s.camera.height = 5.0;
  s.primitives.push_back(p);
  return s;
}

// The projected chord error of `mesh` measured with 12 subdivisions per edge, from first
// principles: window = worldToWindow · X / w, closest point by Newton projection.
double independentPixelError(const TriangleMesh3& mesh, std::size_t surface, const Primitive& p, const Scene& s) {
  const Eigen::Matrix4d M = s.camera.worldToWindow(s.width, s.height);
  auto win = [&](const Vector3d& x) {
    const Eigen::Vector4d w = M * x.homogeneous();
    return Eigen::Vector3d(w.head<3>() / w.w());
  };
  double worst = 0;  // surface triangles only (caps are planar)
  const int m = 12;
  for (std::size_t k = 0; k < surface; ++k) {
    const auto& t = mesh.triangles[k];
    const Vector3d& a = mesh.positions[std::size_t(t[0])];
    const Vector3d& b = mesh.positions[std::size_t(t[1])];
    const Vector3d& c = mesh.positions[std::size_t(t[2])];
    for (int i = 0; i <= m; ++i)
      for (int j = 0; i + j <= m; ++j) {
        const Vector3d x = (double(i) * a + double(j) * b + double(m - i - j) * c) / double(m);
        const Vector3d wx = win(x);
        if (wx.x() < 0 || wx.x() > s.width || wx.y() < 0 || wx.y() > s.height || wx.z() < 0 || wx.z() > 1) continue;
        const Eigen::Vector4d hq = M * closestPointOnQuadric(p.quadric, x).homogeneous();
        if (!(hq.w() > 0)) return 1e300;  // the closest point behind the eye: not a chord error
        const Vector3d wq = hq.head<3>() / hq.w();
        worst = std::max(worst, (wx.head<2>() - wq.head<2>()).norm());
      }
  }
  return worst;
}

}  // namespace

TEST(ScreenSpaceTessellation, AchievedPixelErrorWithinBoundAndCountFalls) {
  for (Camera::Type type : {Camera::Type::Perspective, Camera::Type::Orthographic})
    for (const Case& c : naturalQuadrics()) {
      const Scene s = sceneOf(c.prim, type);
      std::size_t previous = 0;
      // Under the sanitizers two of the tolerances (tests/sanitized_build.h).
      const std::vector<double> tolerances =
          kSanitizedBuild ? std::vector<double>{0.5, 2.0} : std::vector<double>{0.25, 0.5, 1.0, 2.0, 4.0};
      for (double eps : tolerances) {
        TessellationOptions o;
        o.pixel_error = eps;
        TessellationReport rep;
        const TriangleMesh3 mesh = tessellateScene(s, o, &rep);
        const std::string what = c.name + (type == Camera::Type::Perspective ? " persp" : " ortho") + " eps " +
                                 std::to_string(eps);
        ASSERT_GT(mesh.size(), 0u) << what;
        EXPECT_LE(rep.max_pixel_error, eps) << what;
        EXPECT_GT(rep.max_pixel_error, 0.0) << what;
        EXPECT_GT(rep.mean_pixel_error, 0.0) << what;
        EXPECT_LE(rep.mean_pixel_error, rep.max_pixel_error) << what;
        const ScreenView view(s.camera, s.width, s.height);
        const PrimitiveTessellation t =
            tessellatePrimitive(c.prim, o, &s.camera, double(s.width) / s.height, &view);
        EXPECT_EQ(t.mesh.size(), mesh.size()) << what;
        EXPECT_LE(independentPixelError(t.mesh, t.surface_triangles, c.prim, s), eps) << what;
        if (previous) { EXPECT_LT(mesh.size(), previous) << what; }
        previous = mesh.size();
      }
    }
}

TEST(ScreenSpaceTessellation, ChordAndPixelErrorAreExclusive) {
  const Scene s = sceneOf(makeSphere(Vector3d::Zero(), 1.0), Camera::Type::Perspective);
  TessellationOptions o;
  o.pixel_error = 1;
  o.chord_error = 0.01;
  try {
    tessellateScene(s, o);
    FAIL() << "both bounds accepted";
  } catch (const std::invalid_argument& e) {
    EXPECT_NE(std::string(e.what()).find("chord_error"), std::string::npos);
    EXPECT_NE(std::string(e.what()).find("pixel_error"), std::string::npos);
  }
}

TEST(ScreenSpaceTessellation, PixelsPerUnitBoundsTheProjection) {
  // Random displacements at random points: the window displacement never exceeds
  // pixelsPerUnit · |d| (to first order), and reaches it within a few per cent somewhere.
  Camera cam;
  cam.eye = Vector3d(1, 2, 6);
  const ScreenView view(cam, 640, 480);
  std::srand(7);
  auto rnd = [] { return 2.0 * std::rand() / RAND_MAX - 1.0; };
  double best = 0;
  for (int i = 0; i < 2000; ++i) {
    const Vector3d p(2 * rnd(), 2 * rnd(), 2 * rnd());
    const Vector3d d = 1e-6 * Vector3d(rnd(), rnd(), rnd()).normalized();
    const double moved = (view.project(p + d) - view.project(p)).norm();
    const double bound = view.pixelsPerUnit(p) * d.norm();
    EXPECT_LE(moved, bound * (1 + 1e-4));
    best = std::max(best, moved / bound);
  }
  EXPECT_GT(best, 0.95);
}

TEST(ScreenSpaceTessellation, OffScreenPiecesGetTheCoarsestMesh) {
  Scene s = sceneOf(makeSphere(Vector3d(0, 0, 0), 1.0), Camera::Type::Perspective);
  s.primitives.push_back(makeSphere(Vector3d(0, 0, 40), 1.0));  // behind the eye
  TessellationOptions o;
  o.pixel_error = 0.25;
  TessellationReport rep;
  const TriangleMesh3 mesh = tessellateScene(s, o, &rep);
  std::size_t behind = 0, seen = 0;
  for (std::size_t t = 0; t < mesh.size(); ++t) (mesh.primitive[t] == 1 ? behind : seen)++;
  EXPECT_GT(seen, 20 * behind);
  EXPECT_GT(behind, 0u);
}
