// The shared boundary's degenerate cases, one at a time (shared_polyline.h, boundary_strip.h):
// two pieces whose faces on a shared plane meet along a line share no arc; arcs shorter than
// the trace's probe are found; a piece whose polylines all lie on two of its planes at once (a
// sliver) draws nothing when it lies within the tolerance of them, and is refused when it does
// not; an open path whose ends are a rounding apart, with nothing kept to end on, is closed; a
// spur from a corner is left out. Each case was met on the B-spline
// scenes (docs/COMPARE.md, "Cracks in the drawn facets"); each has a control that must not
// take the degenerate way.
#include <gtest/gtest.h>

#include <cmath>
#include <vector>

#include "modeling/tessellation/boundary_strip.h"
#include "modeling/tessellation/shared_polyline.h"
#include "modeling/tessellation/tessellation.h"

using namespace qacc;
using namespace qacc::tess;
using Eigen::Vector3d;
using Eigen::Vector4d;

namespace {

Quadric unitSphere() { return Quadric::fromPlainCoefficients(1, 1, 1, 0, 0, 0, 0, 0, 0, -1); }

// One surface triangle on the unit sphere, its normals the sphere's.
TriangleMesh3 triangleOnSphere(const Vector3d& a, const Vector3d& b, const Vector3d& c) {
  TriangleMesh3 m;
  m.positions = {a, b, c};
  m.normals = {a.normalized(), b.normalized(), c.normalized()};
  m.triangles = {{0, 1, 2}};
  return m;
}

}  // namespace

// On the plane z = 0 the unit circle; the face is y - z <= 0 and -y - 2z <= 0, two different
// planes whose traces on z = 0 are y <= 0 and y >= 0: the pieces meet along y = 0 only, where
// the circle crosses it at (±1, 0, 0). No arc, though both points are on every plane of the
// face. Control: the second plane moved to y >= -0.5 leaves a band with two arcs in it.
TEST(SharedCurveEnds, FacesThatMeetAlongALineOfThePlaneShareNoArc) {
  const Quadric q = unitSphere();
  const HalfSpace h(Vector4d(0, 0, 1, 0));
  const std::vector<HalfSpace> line{HalfSpace(Vector4d(0, 1, -1, 0)), HalfSpace(Vector4d(0, -1, -2, 0))};
  EXPECT_TRUE(sharedCurveEnds(q, h, line).empty());
  const std::vector<HalfSpace> band{HalfSpace(Vector4d(0, 1, -1, 0)), HalfSpace(Vector4d(0, -1, -2, -0.5))};
  const std::vector<Vector3d> ends = sharedCurveEnds(q, h, band);
  EXPECT_EQ(ends.size(), 4u);
  for (const Vector3d& e : ends) {
    EXPECT_NEAR(e.norm(), 1.0, 1e-12);
    EXPECT_NEAR(e.z(), 0.0, 1e-12);
  }
}

// A sliver: its one polyline segment found on two of its shared planes (its two neighbours
// end on the same chord), its third corner 1e-4 off the chord. Within the tolerance (1e-3) the
// piece draws nothing; at 0.02 off the chord it is refused and left as it was.
TEST(ZipBoundaryStrip, SliverWithinTheToleranceOfItsDoubledChordDrawsNothing) {
  const Quadric q = unitSphere();
  const Vector3d a(0, 0, 1), b = Vector3d(0.01, 0, 1).normalized();
  const std::vector<HalfSpace> planes{HalfSpace(Vector4d(0, 1, 0, 0)), HalfSpace(Vector4d(0, -1, 0, 0))};
  const std::vector<std::vector<Vector3d>> polylines{{a, b}, {b, a}};
  PolylineTolerance tol;
  tol.world = 1e-3;
  for (double off : {1e-4, 0.02}) {
    TriangleMesh3 mesh = triangleOnSphere(a, b, Vector3d(0.005, off, 1).normalized());
    std::size_t surface = 1;
    const bool zipped = zipBoundaryStrip(mesh, surface, planes, polylines, q, tol);
    if (off < tol.world) {
      EXPECT_TRUE(zipped);
      EXPECT_EQ(surface, 0u);
      EXPECT_EQ(mesh.triangles.size(), 0u);
    } else {
      EXPECT_FALSE(zipped) << off;
      EXPECT_EQ(surface, 1u);
      EXPECT_EQ(mesh.triangles.size(), 1u);
    }
  }
}

// A piece whose boundary is all shared, every triangle touching it: its polylines run round
// it but for an arc 1e-5 long (too short for its ends to be found) at one corner. The path is
// closed by the edge between its ends: the new triangles use every polyline segment once and
// the closing edge once, nothing else open. Control: a gap of 0.05 is not closed (refused).
TEST(ZipBoundaryStrip, PathWhoseEndsAreARoundingApartIsClosed) {
  const Quadric q = unitSphere();
  const Vector3d p0(0, 0, 1), p1 = Vector3d(0.1, 0, 1).normalized(), p2 = Vector3d(0, 0.1, 1).normalized();
  const std::vector<HalfSpace> planes{HalfSpace(Vector4d(0, -1, 0, 0)), HalfSpace(Vector4d(-1, 0, 0, 0)),
                                      HalfSpace(Vector4d(p1.cross(p2).x(), p1.cross(p2).y(), p1.cross(p2).z(), 0))};
  PolylineTolerance tol;
  tol.world = 1e-2;
  for (double gap : {1e-5, 0.05}) {
    const Vector3d p0b = Vector3d(0, gap, 1).normalized();  // on x = 0, like p0
    const std::vector<std::vector<Vector3d>> polylines{{p0, p1}, {p1, p2}, {p2, p0b}};
    TriangleMesh3 mesh = triangleOnSphere(p0, p1, p2);
    std::size_t surface = 1;
    const bool zipped = zipBoundaryStrip(mesh, surface, planes, polylines, q, tol);
    if (gap > 1e-3) {
      EXPECT_FALSE(zipped);
      continue;
    }
    ASSERT_TRUE(zipped);
    EXPECT_EQ(surface, mesh.triangles.size());
    const EdgeUse use = edgeUse(mesh);
    EXPECT_EQ(use.overused, 0u);
    EXPECT_EQ(use.degenerate, 0u);
    auto isOpen = [&](const Vector3d& x, const Vector3d& y) {
      for (const OpenEdge& e : use.open)
        if ((e.a == x && e.b == y) || (e.a == y && e.b == x)) return true;
      return false;
    };
    EXPECT_EQ(use.open.size(), 4u);
    EXPECT_TRUE(isOpen(p0, p1));
    EXPECT_TRUE(isOpen(p1, p2));
    EXPECT_TRUE(isOpen(p2, p0b));
    EXPECT_TRUE(isOpen(p0b, p0));
  }
}

// Arcs shorter than the trace's probe: the unit circle on z = 0 within the band
// -1e-5 <= y <= 0 is two arcs about 1e-5 long at (±1, 0, 0), 2 apart. Each end is traced into
// the face with a probe shorter than the way to the nearest other end (1e-3 of the span, 0.002,
// would step out of the band both ways and lose both arcs).
TEST(SharedCurveEnds, ArcsShorterThanTheProbeAreFound) {
  const Quadric q = unitSphere();
  const HalfSpace h(Vector4d(0, 0, 1, 0));
  const std::vector<HalfSpace> band{HalfSpace(Vector4d(0, 1, 0, 0)), HalfSpace(Vector4d(0, -1, 0, -1e-5))};
  const std::vector<Vector3d> ends = sharedCurveEnds(q, h, band);
  ASSERT_EQ(ends.size(), 4u);
  for (std::size_t a = 0; a < 4; a += 2) {
    EXPECT_LT((ends[a] - ends[a + 1]).norm(), 2e-5) << a;
    EXPECT_NEAR(std::abs(ends[a].x()), 1.0, 1e-9) << a;
  }
}

// A spur: the piece's polylines run round a triangle and, from one of its corners, along a
// segment no other of them reaches (a neighbour's arc the piece touches only at that corner).
// The spur is left out: the new triangles use the three sides once each and nothing else.
TEST(ZipBoundaryStrip, SpurFromACornerIsLeftOut) {
  const Quadric q = unitSphere();
  const Vector3d p0(0, 0, 1), p1 = Vector3d(0.1, 0, 1).normalized(), p2 = Vector3d(0, 0.1, 1).normalized();
  const Vector3d spur = Vector3d(-0.05, -0.05, 1).normalized();
  const std::vector<HalfSpace> planes{HalfSpace(Vector4d(0, -1, 0, 0)), HalfSpace(Vector4d(-1, 0, 0, 0)),
                                      HalfSpace(Vector4d(p1.cross(p2).x(), p1.cross(p2).y(), p1.cross(p2).z(), 0))};
  PolylineTolerance tol;
  tol.world = 1e-2;
  TriangleMesh3 mesh = triangleOnSphere(p0, p1, p2);
  std::size_t surface = 1;
  ASSERT_TRUE(zipBoundaryStrip(mesh, surface, planes, {{p0, p1}, {p1, p2}, {p2, p0}, {p0, spur}}, q, tol));
  const EdgeUse use = edgeUse(mesh);
  EXPECT_EQ(use.overused, 0u);
  EXPECT_EQ(use.open.size(), 3u);
  for (const OpenEdge& e : use.open) EXPECT_TRUE(e.a != spur && e.b != spur);
}
