// Tessellation of primitives (design §3.3): vertices on the surface, watertight solids,
// chord error against the analytic bound, triangle counts.
#include <gtest/gtest.h>

#include <cmath>
#include <string>

#include <omp.h>

#include "modeling/geometry/natural_quadrics.h"
#include "modeling/loader/scene_loader.h"
#include "modeling/tessellation/tessellation.h"

using namespace qacc;
using Eigen::Vector3d;

namespace {

// Exact chord error of a triangle inscribed in a sphere of radius r: the plane's closest
// point to the centre is the circumcentre; if it falls outside the triangle the farthest
// point from the sphere is the midpoint of the longest edge.
double inscribedChordError(const Vector3d& a, const Vector3d& b, const Vector3d& c, double r) {
  const Vector3d ab = b - a, ac = c - a;
  const Vector3d n = ab.cross(ac);
  const Vector3d cc = a + (ac.squaredNorm() * n.cross(ab) + ab.squaredNorm() * ac.cross(n)) / (2 * n.squaredNorm());
  const double la = (b - c).squaredNorm(), lb = (c - a).squaredNorm(), lc = (a - b).squaredNorm();
  const bool acute = la <= lb + lc && lb <= la + lc && lc <= la + lb;
  const double rho2 = acute ? (cc - a).squaredNorm() : std::max({la, lb, lc}) / 4.0;
  return r - std::sqrt(r * r - rho2);
}

double maxVertexDistance(const PrimitiveTessellation& t, const Quadric& q) {
  double d = 0;
  for (std::size_t i = 0; i < t.surface_triangles; ++i)
    for (int k = 0; k < 3; ++k) d = std::max(d, distanceToQuadric(q, t.mesh.positions[std::size_t(t.mesh.triangles[i][k])]));
  return d;
}

}  // namespace

TEST(Tessellation, SphereChordErrorFallsAndMatchesAnalyticBound) {
  const double r = 2.0;
  const Primitive s = makeSphere(Vector3d(1, -2, 0.5), r);
  double previous = 1e300;
  for (int level : {8, 32, 128, 512, 2048}) {
    TessellationOptions o;
    o.triangles = level;
    const PrimitiveTessellation t = tessellatePrimitive(s, o);
    EXPECT_EQ(t.method, TessellationMethod::Parametric);
    EXPECT_LE(t.surface_triangles, std::size_t(level));
    EXPECT_GE(t.surface_triangles, std::size_t(level * 0.75));
    double exact = 0;
    for (const auto& tri : t.mesh.triangles)
      exact = std::max(exact, inscribedChordError(t.mesh.positions[tri[0]] - Vector3d(1, -2, 0.5),
                                                  t.mesh.positions[tri[1]] - Vector3d(1, -2, 0.5),
                                                  t.mesh.positions[tri[2]] - Vector3d(1, -2, 0.5), r));
    EXPECT_LE(t.max_chord_error, exact * (1 + 1e-9) + 1e-12) << level;
    EXPECT_GE(t.max_chord_error, 0.95 * exact) << level;
    EXPECT_LT(t.max_chord_error, previous) << level;
    previous = t.max_chord_error;
    // Closed form for the lat-long grid: no triangle is finer than the equatorial
    // sagitta of one longitude step, r (1 − cos(π / nu)) with 2 nu (nv − 1) triangles.
    EXPECT_LT(maxVertexDistance(t, s.quadric), 1e-12);
    EXPECT_TRUE(isWatertight(t.mesh)) << level;
  }
  EXPECT_LT(previous, 0.005 * r);
}

TEST(Tessellation, ChordErrorBoundMode) {
  const Primitive s = makeSphere(Vector3d::Zero(), 1.0);
  TessellationOptions o;
  o.chord_error = 1e-3;
  const PrimitiveTessellation t = tessellatePrimitive(s, o);
  EXPECT_LE(t.max_chord_error, 1e-3);
  EXPECT_GT(t.max_chord_error, 1e-3 / 8);  // not grossly over-refined (area ~ 1/error)
}

TEST(Tessellation, SolidsAreWatertightWithVerticesOnSurface) {
  std::vector<Primitive> prims = {
      makeCylinder(Vector3d(0, 0, 0), Vector3d(1, 2, 0.5), 0.7),
      makeCone(Vector3d(0, 1, 0), Vector3d(1, -1, 0.3), 0.8),
      makeHyperboloid1(Vector3d(1, 0.7, 0.5), 2.0),
      makeParaboloid(1.0, 0.6, 1.5),
      makeEllipsoid(Vector3d(0.2, 0.1, 0), Vector3d(1, 2, 0.5)),
  };
  // A sphere cut by two oblique planes: caps meet along a plane-plane line.
  Primitive cut = makeSphere(Vector3d::Zero(), 1.0);
  cut.clip = {HalfSpace(Eigen::Vector4d(1, 0.2, 0, -0.3)), HalfSpace(Eigen::Vector4d(0, 1, 0.3, -0.2))};
  prims.push_back(cut);
  // Three planes meeting inside the solid: the caps turn at the polytope's corner.
  Primitive corner = makeSphere(Vector3d::Zero(), 1.0);
  corner.clip = {HalfSpace(Eigen::Vector4d(1, 0, 0, -0.3)), HalfSpace(Eigen::Vector4d(0, 1, 0, -0.2)),
                 HalfSpace(Eigen::Vector4d(0, 0, 1, -0.1))};
  prims.push_back(corner);
  for (std::size_t i = 0; i < prims.size(); ++i) {
    Primitive p = prims[i];
    p.solid = true;
    TessellationOptions o;
    o.triangles = 200;
    const PrimitiveTessellation t = tessellatePrimitive(p, o);
    EXPECT_EQ(t.method, TessellationMethod::Parametric) << i;
    EXPECT_GT(t.surface_triangles, 50u) << i;
    if (!p.clip.empty()) { EXPECT_GT(t.cap_triangles, 0u) << i; }
    EXPECT_TRUE(isWatertight(t.mesh)) << i;
    EXPECT_LT(maxVertexDistance(t, p.quadric), 1e-9) << i;
    // Every vertex respects the clip polyhedron (up to the bisection tolerance).
    for (const auto& v : t.mesh.positions)
      for (const auto& h : p.clip) EXPECT_LE(h.eval(v), 1e-9) << i;
    // Normals: unit, and along ±gradient on the surface.
    for (std::size_t k = 0; k < t.surface_triangles; ++k)
      for (int c = 0; c < 3; ++c) {
        const Vector3d& n = t.mesh.normals[std::size_t(t.mesh.triangles[k][c])];
        const Vector3d& x = t.mesh.positions[std::size_t(t.mesh.triangles[k][c])];
        EXPECT_NEAR(n.norm(), 1.0, 1e-12);
        const Vector3d g = p.quadric.gradient(x);
        if (g.norm() > 1e-6) { EXPECT_GT(std::abs(n.dot(g.normalized())), 1 - 1e-9) << i; }
      }
    // Surface only: open (no caps), so not watertight.
    p.solid = false;
    const PrimitiveTessellation open = tessellatePrimitive(p, o);
    EXPECT_EQ(open.cap_triangles, 0u);
    if (!p.clip.empty()) { EXPECT_FALSE(isWatertight(open.mesh)) << i; }
  }
}

TEST(Tessellation, CylinderCapAreaAndCount) {
  Primitive c = makeCylinder(Vector3d(0, 0, 0), Vector3d(0, 0, 3), 1.0);
  c.solid = true;
  TessellationOptions o;
  o.triangles = 64;
  const PrimitiveTessellation t = tessellatePrimitive(c, o);
  EXPECT_EQ(t.surface_triangles, 64u);  // ruled: one band of 2 nu triangles
  double area = 0;
  for (std::size_t k = t.surface_triangles; k < t.mesh.size(); ++k) {
    const auto& tri = t.mesh.triangles[k];
    area += 0.5 * (t.mesh.positions[tri[1]] - t.mesh.positions[tri[0]]).cross(t.mesh.positions[tri[2]] - t.mesh.positions[tri[0]]).norm();
  }
  // Two regular 32-gons inscribed in the unit circle.
  EXPECT_NEAR(area, 2 * 0.5 * 32 * std::sin(2 * M_PI / 32), 1e-9);
}

TEST(Tessellation, TriangleIsItself) {
  const Vector3d a(0, 0, 1), b(1, 0, 1.5), c(0, 2, 1);
  Primitive t = makeTriangle(a, b, c);
  const PrimitiveTessellation m = tessellatePrimitive(t, TessellationOptions());
  EXPECT_EQ(m.method, TessellationMethod::Planar);
  ASSERT_GE(m.mesh.size(), 1u);
  double area = 0;
  for (const auto& tri : m.mesh.triangles)
    area += 0.5 * (m.mesh.positions[tri[1]] - m.mesh.positions[tri[0]]).cross(m.mesh.positions[tri[2]] - m.mesh.positions[tri[0]]).norm();
  EXPECT_NEAR(area, 0.5 * (b - a).cross(c - a).norm(), 1e-9);
  for (const auto& v : m.mesh.positions) {
    const double d = std::min({(v - a).norm(), (v - b).norm(), (v - c).norm()});
    EXPECT_LT(d, 1e-9);
  }
}

TEST(Tessellation, MarchingTetrahedraForGeneralPieces) {
  // Hyperbolic paraboloid clipped to a box: no parametric grid, marching tetrahedra.
  Camera cam;
  cam.eye = Vector3d(0, -4, 3);
  const Primitive p = makeHyperbolicParaboloid(1.0, 1.0, 1.0);
  double previous = 1e300;
  std::size_t prevCount = 0;
  for (int level : {50, 200, 800}) {
    TessellationOptions o;
    o.triangles = level;
    const PrimitiveTessellation t = tessellatePrimitive(p, o, &cam, 1.0);  // z unbounded: frustum
    EXPECT_EQ(t.method, TessellationMethod::MarchingTetrahedra);
    EXPECT_GT(t.mesh.size(), prevCount);
    EXPECT_LT(t.max_chord_error, previous);
    EXPECT_LT(t.max_chord_error, 0.1);
    for (const auto& v : t.mesh.positions)
      for (const auto& h : p.clip) EXPECT_LE(h.eval(v), 1e-9);
    previous = t.max_chord_error;
    prevCount = t.mesh.size();
  }
}

TEST(Tessellation, UnboundedPiecesLimitedToFrustum) {
  Camera cam;
  cam.eye = Vector3d(0, 2, 8);
  const Primitive plane = makePlane(Vector3d(0, -1, 0), Vector3d(0, 1, 0));
  EXPECT_EQ(tessellatePrimitive(plane, TessellationOptions()).mesh.size(), 0u);  // no camera: nothing
  const PrimitiveTessellation t = tessellatePrimitive(plane, TessellationOptions(), &cam, 4.0 / 3.0);
  EXPECT_GE(t.mesh.size(), 2u);
  for (const auto& v : t.mesh.positions) EXPECT_NEAR(v.y(), -1.0, 1e-9);
}

// A scene's mesh is assembled in parallel from its pieces (each copied into its own slice):
// the same arrays, in scene order, and the same report for any thread count — pieces with
// shared boundaries (macropatch_g1) and an exact surface drawn at its first piece (torus).
TEST(Tessellation, SceneMeshIdenticalForAnyThreadCount) {
  for (const char* name : {"macropatch_g1.json", "torus.json"}) {
    const Scene s = loadScene(std::string(QACC_SOURCE_DIR) + "/scenes/" + name);
    TessellationOptions o;
    o.triangles = 16;
    const int before = omp_get_max_threads();
    omp_set_num_threads(1);
    TessellationReport r1, r3;
    const TriangleMesh3 m1 = tessellateScene(s, o, &r1);
    omp_set_num_threads(3);
    const TriangleMesh3 m3 = tessellateScene(s, o, &r3);
    omp_set_num_threads(before);
    ASSERT_GT(m1.size(), 0u) << name;
    EXPECT_TRUE(m1.positions == m3.positions) << name;
    EXPECT_TRUE(m1.normals == m3.normals) << name;
    EXPECT_TRUE(m1.triangles == m3.triangles) << name;
    EXPECT_TRUE(m1.object == m3.object && m1.material == m3.material && m1.primitive == m3.primitive) << name;
    EXPECT_EQ(r1.triangles, r3.triangles) << name;
    EXPECT_EQ(r1.max_chord_error, r3.max_chord_error) << name;
    // An exact surface's mean error is an OpenMP sum (marching_tetrahedra.cpp): equal up to
    // its order.
    EXPECT_NEAR(r1.mean_chord_error, r3.mean_chord_error, 1e-12 * r1.mean_chord_error) << name;
    // Every triangle's ids are its primitive's (or, for an exact surface, its first piece's).
    for (std::size_t t = 0; t < m1.size(); ++t) {
      const int p = m1.primitive[t];
      ASSERT_TRUE(p >= 0 && std::size_t(p) < s.primitives.size()) << name;
      ASSERT_EQ(m1.object[t], s.primitives[std::size_t(p)].object) << name;
      ASSERT_EQ(m1.material[t], s.primitives[std::size_t(p)].material) << name;
    }
  }
}
