// The range of a B-spline height field over a polygon (modeling/splines/height_field_bound.h)
// and the view culling it drives (SimplexSpline2::cells with a view): with random control
// values, every sampled value of F over a polygon, and of every cell's polynomial over its
// closed polygon, lies inside the polygon's range — near the triangulation's boundary (no
// display domain) and inside it, with knot clouds small and large; also where the basis is
// not a partition of unity far from the boundary (knot clouds of 0.9 x the shortest edge),
// which the convex hull of the coefficients, the bound used there before, missed; and a view
// drops only cells whose surface projects outside the image.
#include <gtest/gtest.h>

#include <cmath>
#include <random>
#include <utility>
#include <vector>

#include "modeling/splines/height_field_bound.h"
#include "modeling/splines/simplex_spline2.h"
#include "tests/modeling/triangle_grid.h"

using namespace qacc;
using Eigen::Vector2d;
using Eigen::Vector3d;

namespace {

// Random coefficients in [lo, hi].
void randomise(SimplexSpline2& s, std::mt19937& rng, double lo, double hi) {
  std::uniform_real_distribution<double> u(lo, hi);
  std::vector<std::vector<double>> c(s.coefficients().size());
  for (std::size_t t = 0; t < c.size(); ++t) {
    c[t].resize(SimplexSpline2::multiIndices(s.degree()).size());
    for (double& x : c[t]) x = u(rng);
  }
  s.setCoefficients(c);
}

// A random point of the closed convex polygon (a fan triangle from its first corner); with
// `interior`, strictly inside.
Vector2d pointIn(const std::vector<Vector2d>& poly, std::mt19937& rng, bool interior) {
  std::uniform_real_distribution<double> u(interior ? 1e-6 : 0.0, interior ? 1 - 1e-6 : 1.0);
  const std::size_t k = 1 + std::size_t(rng() % (poly.size() - 2));
  double a = u(rng), b = u(rng);
  if (a + b > 1) a = 1 - a, b = 1 - b;
  return poly[0] + a * (poly[k] - poly[0]) + b * (poly[k + 1] - poly[0]);
}

bool inTriangle(const std::vector<Vector2d>& tri, const Vector2d& p) {
  auto side = [](const Vector2d& a, const Vector2d& b, const Vector2d& q) {
    return (b - a).x() * (q - a).y() - (b - a).y() * (q - a).x();
  };
  const double s0 = side(tri[0], tri[1], p), s1 = side(tri[1], tri[2], p), s2 = side(tri[2], tri[0], p);
  return (s0 >= 0 && s1 >= 0 && s2 >= 0) || (s0 <= 0 && s1 <= 0 && s2 <= 0);
}

}  // namespace

TEST(HeightFieldBound, HoldsEverySampledValueOfRandomSplines) {
  std::mt19937 rng(13);
  int samples = 0;
  // G0 knots sit on their vertices; G1 clouds of 0.2 and 0.6 x the shortest incident edge.
  for (const auto& [radius, g1] : std::vector<std::pair<double, bool>>{{0.2, false}, {0.2, true}, {0.6, true}})
    for (bool domain : {false, true})
      for (int trial = 0; trial < 3; ++trial) {
        const TriangleGrid g = triangleGrid(4, -2, 2);
        SimplexSpline2 s(2, g.v, g.t, knotClouds(g.v, g.t, 2, g1, radius));
        if (domain) s.setDomain(Eigen::AlignedBox2d(Vector2d(-1.5, -1.5), Vector2d(1.5, 1.5)));
        // Positive values show a sum of the basis below 1 near the boundary; mixed signs
        // and a large offset the rest.
        if (trial == 0) randomise(s, rng, 0.5, 1.5);
        if (trial == 1) randomise(s, rng, -1.0, 1.0);
        if (trial == 2) randomise(s, rng, 99.0, 101.0);
        const HeightFieldBound bound(s);
        const auto cells = s.cells();
        for (const auto& t : s.triangles()) {
          const std::vector<Vector2d> tri = {s.vertices()[std::size_t(t[0])], s.vertices()[std::size_t(t[1])],
                                             s.vertices()[std::size_t(t[2])]};
          const HeightFieldBound::Range r = bound.over(tri);
          for (int k = 0; k < 50; ++k) {
            const Vector2d p = pointIn(tri, rng, true);
            const double f = s.eval(p);
            ++samples;
            ASSERT_GE(f, r.lo) << "g1 " << g1 << " trial " << trial << " at " << p.transpose();
            ASSERT_LE(f, r.hi) << "g1 " << g1 << " trial " << trial << " at " << p.transpose();
          }
          // The cells inside the triangle: their polynomials over their closed polygons.
          for (const auto& c : cells) {
            Vector2d centre = Vector2d::Zero();
            for (const Vector2d& v : c.polygon) centre += v / double(c.polygon.size());
            if (!inTriangle(tri, centre)) continue;
            for (int k = 0; k < 10; ++k) {
              const Vector2d p = k < int(c.polygon.size()) ? c.polygon[std::size_t(k)] : pointIn(c.polygon, rng, false);
              const double f = c.poly.eval(Vector3d(p.x(), p.y(), 0));
              ++samples;
              ASSERT_GE(f, r.lo) << "cell of g1 " << g1 << " trial " << trial << " at " << p.transpose();
              ASSERT_LE(f, r.hi) << "cell of g1 " << g1 << " trial " << trial << " at " << p.transpose();
            }
            // And the cell's own polygon, a smaller one.
            const HeightFieldBound::Range rc = bound.over(c.polygon);
            for (int k = 0; k < 5; ++k) {
              const Vector2d p = pointIn(c.polygon, rng, false);
              const double f = c.poly.eval(Vector3d(p.x(), p.y(), 0));
              ASSERT_GE(f, rc.lo);
              ASSERT_LE(f, rc.hi);
            }
          }
        }
      }
  EXPECT_GT(samples, 50000);
  std::printf("%d samples\n", samples);
}

TEST(HeightFieldBound, HoldsWhereTheBasisIsNotAPartitionOfUnity) {
  // Knot clouds of 0.9 x the shortest incident edge: far inside the triangulation (farther
  // than the clouds' reach from its boundary) the basis sums to more or less than 1 at some
  // points. With every coefficient 1, F is that sum; the convex hull of the coefficients, [1, 1],
  // missed it there.
  const TriangleGrid g = triangleGrid(6, -3, 3);
  SimplexSpline2 s(2, g.v, g.t, knotClouds(g.v, g.t, 2, true, 0.9));
  s.setCoefficients(std::vector<std::vector<double>>(s.triangles().size(), std::vector<double>(6, 1.0)));
  ASSERT_LT(s.knotReach(), 1.0);
  std::mt19937 rng(21);
  std::uniform_real_distribution<double> u(-1.5, 1.5);  // beyond the reach from the boundary at ±3
  Vector2d worst = Vector2d::Zero();
  double excess = 0;
  for (int k = 0; k < 20000; ++k) {
    const Vector2d p(u(rng), u(rng));
    const double e = std::fabs(s.eval(p) - 1);
    if (e > excess) excess = e, worst = p;
  }
  EXPECT_GT(excess, 1e-3) << "the basis is a partition of unity here: the test shows nothing";
  const HeightFieldBound bound(s);
  // Squares around the worst point, and every triangle of the grid, hold their sampled values.
  for (double h : {0.001, 0.01, 0.1}) {
    const std::vector<Vector2d> square = {worst + Vector2d(-h, -h), worst + Vector2d(h, -h), worst + Vector2d(h, h),
                                          worst + Vector2d(-h, h)};
    const HeightFieldBound::Range r = bound.over(square);
    const double f = s.eval(worst);
    EXPECT_GE(f, r.lo) << "square of half-side " << h << " at " << worst.transpose();
    EXPECT_LE(f, r.hi) << "square of half-side " << h << " at " << worst.transpose();
  }
  for (const auto& t : s.triangles()) {
    const std::vector<Vector2d> tri = {s.vertices()[std::size_t(t[0])], s.vertices()[std::size_t(t[1])],
                                       s.vertices()[std::size_t(t[2])]};
    const HeightFieldBound::Range r = bound.over(tri);
    for (int k = 0; k < 200; ++k) {
      const Vector2d p = pointIn(tri, rng, true);
      const double f = s.eval(p);
      ASSERT_GE(f, r.lo) << "at " << p.transpose();
      ASSERT_LE(f, r.hi) << "at " << p.transpose();
    }
  }
  std::printf("the basis sums to 1 %+.4f at (%.4f, %.4f)\n", s.eval(worst) - 1, worst.x(), worst.y());
}

TEST(HeightFieldBound, ViewCullingDropsOnlyCellsOutsideTheImage) {
  const TriangleGrid g = triangleGrid(6, -3, 3);
  SimplexSpline2 s(2, g.v, g.t, knotClouds(g.v, g.t, 2, true, 0.2));
  s.setDomain(Eigen::AlignedBox2d(Vector2d(-2, -2), Vector2d(2, 2)));
  s.setCoefficients(s.grevilleCoefficients(Polynomial3::parse("0.35 (x^2 + y^2) - 0.025 (x^4 + y^4) + 0.2 x y")));
  Camera cam;
  cam.eye = Vector3d(4.4, -6.2, 5.0);
  cam.target = Vector3d(0.5, 0.3, 0.2);
  cam.up = Vector3d(0, 0, 1);
  cam.fov_y_deg = 8;
  cam.near = 0.5;
  cam.far = 30;
  const int w = 320, h = 240;
  const ViewVolume view = ViewVolume::of(cam, w, h);
  ViewCullCount count(true);
  const auto all = s.cells();
  const auto kept = s.cells(&view, &count);
  EXPECT_EQ(count.pieces, 32u);  // the triangles that meet the domain [-2, 2]^2
  EXPECT_GE(count.skipped, 5u);
  EXPECT_LT(kept.size(), all.size());
  // The kept cells are the unculled ones, in order; every dropped cell projects off the image.
  const Eigen::Matrix4d M = cam.worldToWindow(w, h);
  std::mt19937 rng(5);
  std::size_t k = 0, dropped = 0;
  for (const auto& c : all) {
    if (k < kept.size() && kept[k].polygon == c.polygon) {
      EXPECT_EQ(kept[k].poly.coefficient(2, 0, 0), c.poly.coefficient(2, 0, 0));
      ++k;
      continue;
    }
    ++dropped;
    for (int i = 0; i < 200; ++i) {
      const Vector2d p = pointIn(c.polygon, rng, false);
      const Eigen::Vector4d q = M * Eigen::Vector4d(p.x(), p.y(), c.poly.eval(Vector3d(p.x(), p.y(), 0)), 1);
      const bool onScreen = q.w() > 0 && q.x() / q.w() >= 0 && q.x() / q.w() <= w && q.y() / q.w() >= 0 &&
                            q.y() / q.w() <= h && q.z() / q.w() >= 0 && q.z() / q.w() <= 1;
      ASSERT_FALSE(onScreen) << "a dropped cell reaches the image at " << p.transpose();
    }
  }
  EXPECT_EQ(k, kept.size());
  EXPECT_GT(dropped, 0u);
}
