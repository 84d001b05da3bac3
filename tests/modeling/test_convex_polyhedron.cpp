// Convex polyhedra cut by planes (the cells of simplex B-spline volumes): a cut by a plane
// gives the expected pieces, repeated cuts partition the tetrahedron (volumes add up, every
// point in exactly one piece), faces carry no redundant plane, triangle crossing tests.
#include <gtest/gtest.h>

#include <random>

#include "modeling/geometry/convex_polyhedron.h"

using namespace qacc;
using Eigen::Vector3d;
using Eigen::Vector4d;

namespace {

struct Fixture {
  std::vector<Vector4d> unit;  // plane table
  ConvexPolyhedron tet;
  Fixture() {
    // The unit corner tetrahedron; face a is opposite corner a, each kept by p·x <= 0.
    const std::array<Vector3d, 4> x = {Vector3d(0, 0, 0), Vector3d(1, 0, 0), Vector3d(0, 1, 0), Vector3d(0, 0, 1)};
    unit = {Vector4d(1, 1, 1, -1) / std::sqrt(3.0), Vector4d(-1, 0, 0, 0), Vector4d(0, -1, 0, 0), Vector4d(0, 0, -1, 0)};
    tet = ConvexPolyhedron::tetrahedron(x, {0, 1, 2, 3}, {false, false, false, false});
  }
  int add(const Vector4d& p) {
    unit.push_back(p / p.head<3>().norm());
    return int(unit.size()) - 1;
  }
};

double volume(const ConvexPolyhedron& p, const std::vector<Vector4d>& unit) {
  double v = 0;
  for (const auto& t : p.fan(unit)) v += std::fabs((t[1] - t[0]).cross(t[2] - t[0]).dot(t[3] - t[0])) / 6.0;
  return v;
}

bool inside(const ConvexPolyhedron& p, const std::vector<Vector4d>& unit, const Vector3d& x, double eps) {
  for (const auto& f : p.faces()) {
    const double s = unit[std::size_t(f.plane)].head<3>().dot(x) + unit[std::size_t(f.plane)].w();
    if ((f.flip ? -s : s) > eps) return false;
  }
  return true;
}

}  // namespace

TEST(ConvexPolyhedron, OneCutGivesTheTwoPieces) {
  Fixture f;
  EXPECT_NEAR(volume(f.tet, f.unit), 1.0 / 6.0, 1e-15);
  const int id = f.add(Vector4d(1, 0, 0, -0.25));  // x = 0.25
  ConvexPolyhedron a, b;
  ASSERT_TRUE(f.tet.split(id, f.unit, 1e-12, a, b));
  EXPECT_EQ(a.vertices().size(), 6u);  // the tetrahedron without its corner x = 1: a wedge
  EXPECT_EQ(a.faces().size(), 5u);
  EXPECT_EQ(b.vertices().size(), 4u);  // the corner: a tetrahedron
  EXPECT_EQ(b.faces().size(), 4u);     // the face x = 0 is gone from it
  EXPECT_NEAR(volume(b, f.unit), 0.75 * 0.75 * 0.75 / 6.0, 1e-15);
  EXPECT_NEAR(volume(a, f.unit) + volume(b, f.unit), 1.0 / 6.0, 1e-15);
  // A plane that only touches a vertex does not cut; clipped keeps or drops all of it.
  const int touch = f.add(Vector4d(1, 1, 1, 0));
  EXPECT_FALSE(f.tet.split(touch, f.unit, 1e-12, a, b));
  EXPECT_EQ(f.tet.clipped(touch, true, f.unit, 1e-12).vertices().size(), 4u);
  EXPECT_TRUE(f.tet.clipped(touch, false, f.unit, 1e-12).empty());
}

TEST(ConvexPolyhedron, RandomCutsPartitionTheTetrahedron) {
  Fixture f;
  std::mt19937 rng(7);
  std::uniform_real_distribution<double> u(-1, 1), w(0.05, 0.3);
  std::vector<ConvexPolyhedron> pieces = {f.tet};
  for (int k = 0; k < 40; ++k) {
    Vector3d n(u(rng), u(rng), u(rng));
    const Vector3d p(w(rng), w(rng), w(rng));
    const int id = f.add(Vector4d(n.x(), n.y(), n.z(), -n.dot(p)));
    std::vector<ConvexPolyhedron> next;
    for (const auto& c : pieces) {
      ConvexPolyhedron a, b;
      if (c.split(id, f.unit, 1e-12, a, b)) {
        next.push_back(std::move(a));
        next.push_back(std::move(b));
      } else {
        next.push_back(c);
      }
    }
    pieces.swap(next);
  }
  EXPECT_GT(pieces.size(), 100u);
  double total = 0;
  for (const auto& c : pieces) {
    total += volume(c, f.unit);
    EXPECT_GE(c.faces().size(), 4u);
    for (const auto& face : c.faces()) {  // every face holds at least three corners
      int on = 0;
      for (const auto& v : c.vertices())
        on += std::fabs(f.unit[std::size_t(face.plane)].head<3>().dot(v.x) + f.unit[std::size_t(face.plane)].w()) < 1e-9;
      EXPECT_GE(on, 3);
    }
    for (const auto& v : c.vertices()) EXPECT_TRUE(inside(c, f.unit, v.x, 1e-9));
  }
  EXPECT_NEAR(total, 1.0 / 6.0, 1e-12);
  std::uniform_real_distribution<double> r(0, 1);
  for (int k = 0; k < 300; ++k) {
    Vector3d x(r(rng), r(rng), r(rng));
    if (x.sum() >= 1) continue;
    int in = 0;
    for (const auto& c : pieces) in += inside(c, f.unit, x, -1e-9);  // strictly inside
    EXPECT_LE(in, 1);
    int closed = 0;
    for (const auto& c : pieces) closed += inside(c, f.unit, x, 1e-9);
    EXPECT_GE(closed, 1);
  }
}

TEST(ConvexPolyhedron, TriangleCrossing) {
  Fixture f;
  const double eps = 1e-12;
  // Through the interior.
  EXPECT_TRUE(f.tet.crossedBy(Vector3d(-1, -1, 0.2), Vector3d(2, -1, 0.2), Vector3d(-1, 2, 0.2), f.unit, eps));
  // In the plane of the face z = 0: touches, does not cross.
  EXPECT_FALSE(f.tet.crossedBy(Vector3d(-1, -1, 0), Vector3d(2, -1, 0), Vector3d(-1, 2, 0), f.unit, eps));
  // Plane crosses, triangle lies beside the tetrahedron.
  EXPECT_FALSE(f.tet.crossedBy(Vector3d(2, 2, 0.2), Vector3d(3, 2, 0.2), Vector3d(2, 3, 0.2), f.unit, eps));
  // A small triangle inside.
  EXPECT_TRUE(f.tet.crossedBy(Vector3d(0.1, 0.1, 0.1), Vector3d(0.2, 0.1, 0.1), Vector3d(0.1, 0.2, 0.15), f.unit, eps));
}
