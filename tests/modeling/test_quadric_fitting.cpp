// Quadric interpolation: Pratt's linear method recovers known quadrics from exact points,
// Bajaj-Ihm recovers them from point/normal pairs and reports the solution space's
// dimension, Guo's Tangent Planes Condition accepts and rejects known cases (and agrees
// with what Bajaj-Ihm finds).
#include <gtest/gtest.h>

#include <cstdio>
#include <random>

#include "modeling/modelers/quadric_fitting.h"
#include "modeling/modelers/revolution.h"

using namespace qacc;
using Eigen::Matrix4d;
using Eigen::Vector3d;

namespace {

// Same surface up to a non-zero scale (either sign): compares normalised coefficients.
double surfaceDistance(const Quadric& a, const Quadric& b) {
  const Matrix4d A = a.Q / a.Q.norm(), B = b.Q / b.Q.norm();
  return std::min((A - B).norm(), (A + B).norm());
}

// A rotated, translated ellipsoid and a parametrisation of it.
struct Ellipsoid {
  Eigen::Matrix3d R;
  Vector3d c{0.3, -0.2, 0.5}, r{1.5, 0.8, 0.6};
  Ellipsoid() { R = Eigen::AngleAxisd(0.7, Vector3d(1, 2, 3).normalized()).toRotationMatrix(); }
  Vector3d point(double th, double ph) const {
    return c + R * Vector3d(r.x() * std::cos(th) * std::sin(ph), r.y() * std::sin(th) * std::sin(ph), r.z() * std::cos(ph));
  }
  Quadric quadric() const {
    Matrix4d D = Matrix4d::Zero();
    D.diagonal() << 1 / (r.x() * r.x()), 1 / (r.y() * r.y()), 1 / (r.z() * r.z()), -1;
    Matrix4d M = Matrix4d::Identity();
    M.topLeftCorner<3, 3>() = R;
    M.topRightCorner<3, 1>() = c;
    return Quadric(D).transformed(M);
  }
  Vector3d normal(double th, double ph) const { return quadric().gradient(point(th, ph)); }
};

}  // namespace

TEST(QuadricInterpolation, PrattGeneralQuadricFromNinePoints) {
  const Ellipsoid e;
  std::mt19937 rng(2);
  std::uniform_real_distribution<double> th(0, 2 * M_PI), ph(0.1, 3.0);
  std::vector<Vector3d> pts;
  for (int i = 0; i < 9; ++i) pts.push_back(e.point(th(rng), ph(rng)));
  const InterpolationResult r = interpolatePoints(pts);
  EXPECT_EQ(r.equations, 9);
  EXPECT_EQ(r.dimension, 1);
  EXPECT_LT(surfaceDistance(r.quadric, e.quadric()), 1e-9);
  // 8 points leave a pencil of quadrics (dimension 2); 20 exact points still give 1.
  pts.pop_back();
  EXPECT_EQ(interpolatePoints(pts).dimension, 2);
  for (int i = 0; i < 12; ++i) pts.push_back(e.point(th(rng), ph(rng)));
  const InterpolationResult many = interpolatePoints(pts);
  EXPECT_EQ(many.dimension, 1);
  EXPECT_LT(surfaceDistance(many.quadric, e.quadric()), 1e-9);
}

TEST(QuadricInterpolation, PrattFamilies) {
  // Sphere from 4 points: centre (1, 2, -1), radius 2.
  const Vector3d c(1, 2, -1);
  const std::vector<Vector3d> sp = {c + Vector3d(2, 0, 0), c + Vector3d(0, 2, 0), c + Vector3d(0, 0, -2),
                                    c + Vector3d(1.2, 1.6, 0)};
  const InterpolationResult s = interpolatePoints(sp, QuadricFamily::Sphere);
  EXPECT_EQ(s.dimension, 1);
  const Quadric truth = Quadric::fromCoefficients(1, 1, 1, 0, 0, 0, -c.x(), -c.y(), -c.z(), c.squaredNorm() - 4);
  EXPECT_LT(surfaceDistance(s.quadric, truth), 1e-12);
  // A fifth point off that sphere: no sphere fits (dimension 0, non-zero residual).
  auto bad = sp;
  bad.push_back(c + Vector3d(0.5, 0, 0));
  const InterpolationResult b = interpolatePoints(bad, QuadricFamily::Sphere);
  EXPECT_EQ(b.dimension, 0);
  EXPECT_GT(b.residual, 1e-3);
  // Revolution about z from 3 profile points agrees with (4.5)-(4.6).
  const RevolutionProfile prof = profileThroughThreePoints({0.5, 0}, {0.9, 1}, {0.7, 2});
  const InterpolationResult rv =
      interpolatePoints({Vector3d(0.5, 0, 0), Vector3d(0, 0.9, 1), Vector3d(-0.7 * 0.6, -0.7 * 0.8, 2)}, QuadricFamily::RevolutionZ);
  EXPECT_EQ(rv.dimension, 1);
  EXPECT_LT(surfaceDistance(rv.quadric, prof.quadric()), 1e-12);
  // Axis-aligned family from 6 points of an axis-aligned ellipsoid.
  const Quadric ax = Quadric::fromCoefficients(1 / 4.0, 1, 1 / 0.25, 0, 0, 0, 0, 0, 0, -1);
  std::vector<Vector3d> ap;
  const double ang[6][2] = {{0.1, 0.4}, {1.3, 1.2}, {2.2, 2.0}, {3.4, 0.9}, {4.4, 2.6}, {5.6, 1.7}};
  for (auto& q : ang)
    ap.push_back(Vector3d(2 * std::cos(q[0]) * std::sin(q[1]), std::sin(q[0]) * std::sin(q[1]), 0.5 * std::cos(q[1])));
  const InterpolationResult a = interpolatePoints(ap, QuadricFamily::AxisAligned);
  EXPECT_EQ(a.dimension, 1);
  EXPECT_LT(surfaceDistance(a.quadric, ax), 1e-12);
}

TEST(QuadricInterpolation, BajajIhmPointNormals) {
  const Ellipsoid e;
  const double t[4][2] = {{0.3, 0.8}, {2.0, 1.4}, {4.1, 2.2}, {5.5, 0.5}};
  std::vector<Vector3d> p, n;
  for (auto& a : t) p.push_back(e.point(a[0], a[1])), n.push_back(e.normal(a[0], a[1]));
  // 4 pairs = 12 equations: the quadric is recovered, solution space of dimension 1.
  const PointNormalResult r4 = interpolatePointNormals(p, n);
  EXPECT_EQ(r4.equations, 12);
  EXPECT_EQ(r4.dimension, 1);
  EXPECT_LT(surfaceDistance(r4.quadric, e.quadric()), 1e-9);
  EXPECT_TRUE(r4.tangent_planes_ok);
  // 3 pairs = 9 equations: reported dimension and tangent planes honoured.
  p.pop_back(), n.pop_back();
  const PointNormalResult r3 = interpolatePointNormals(p, n);
  EXPECT_EQ(r3.equations, 9);
  EXPECT_GE(r3.dimension, 1);
  std::printf("Bajaj-Ihm, 3 point/normal pairs of an ellipsoid: solution space dimension %d\n", r3.dimension);
  EXPECT_TRUE(r3.tangent_planes_ok) << r3.worst_normal_angle_deg << " " << r3.min_gradient_ratio;
  // Sphere family: 2 point/normal pairs of a sphere define it.
  const Vector3d c(0.5, 0.5, 0);
  const PointNormalResult s = interpolatePointNormals({c + Vector3d(1, 0, 0), c + Vector3d(0, 0.6, 0.8)},
                                                      {Vector3d(1, 0, 0), Vector3d(0, 0.6, 0.8)}, QuadricFamily::Sphere);
  EXPECT_EQ(s.dimension, 1);
  EXPECT_LT(surfaceDistance(s.quadric, Quadric::fromCoefficients(1, 1, 1, 0, 0, 0, -c.x(), -c.y(), -c.z(), c.squaredNorm() - 1)), 1e-12);
}

TEST(QuadricInterpolation, GuoTangentPlanesCondition) {
  // Accepts: three points of a sphere with their normals (product exactly 1).
  const std::array<Vector3d, 3> P = {Vector3d(1, 0, 0), Vector3d(0, 0.6, 0.8), Vector3d(-0.48, -0.6, 0.64)};
  const GuoCondition ok = guoTangentPlanesCondition(P, P);
  EXPECT_TRUE(ok.holds);
  EXPECT_FALSE(ok.orthogonal_case);
  EXPECT_NEAR(ok.product, 1.0, 1e-12);
  // ... and on a general ellipsoid.
  const Ellipsoid e;
  const std::array<Vector3d, 3> Pe = {e.point(0.3, 0.8), e.point(2.0, 1.4), e.point(4.1, 2.2)};
  const std::array<Vector3d, 3> Ne = {e.normal(0.3, 0.8), e.normal(2.0, 1.4), e.normal(4.1, 2.2)};
  EXPECT_TRUE(guoTangentPlanesCondition(Pe, Ne).holds);
  // Rejects: one normal tilted; Bajaj-Ihm then finds no quadric with these tangent planes.
  std::array<Vector3d, 3> Nbad = P;
  Nbad[1] = Vector3d(0.2, 0.6, 0.8);
  const GuoCondition no = guoTangentPlanesCondition(P, Nbad);
  EXPECT_FALSE(no.holds);
  EXPECT_GT(std::abs(no.product - 1.0), 0.05);
  const PointNormalResult bi = interpolatePointNormals({P[0], P[1], P[2]}, {Nbad[0], Nbad[1], Nbad[2]});
  EXPECT_FALSE(bi.tangent_planes_ok) << bi.worst_normal_angle_deg << " " << bi.min_gradient_ratio;
  // With the sphere's normals Bajaj-Ihm honours the tangent planes.
  EXPECT_TRUE(interpolatePointNormals({P[0], P[1], P[2]}, {P[0], P[1], P[2]}).tangent_planes_ok);
  // Orthogonal case: two normals orthogonal to their shared edge (points of a cylinder
  // along its axis direction), whatever the third.
  const std::array<Vector3d, 3> Pc = {Vector3d(1, 0, 0), Vector3d(1, 0, 2), Vector3d(0, 1, 1)};
  const std::array<Vector3d, 3> Nc = {Vector3d(1, 0, 0), Vector3d(1, 0.3, 0), Vector3d(0.2, 1, 0.5)};
  const GuoCondition oc = guoTangentPlanesCondition(Pc, Nc);
  EXPECT_TRUE(oc.orthogonal_case);
  EXPECT_TRUE(oc.holds);
}
