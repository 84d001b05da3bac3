// Quadric core: transforms, classification, stable roots.
#include <gtest/gtest.h>

#include <random>

#include "modeling/scene/camera.h"
#include "modeling/geometry/natural_quadrics.h"
#include "modeling/geometry/quadric_type.h"
#include "modeling/geometry/stable_roots.h"

using namespace qacc;

namespace {

Eigen::Matrix3d randomRotation(std::mt19937& rng) {
  std::normal_distribution<double> n;
  Eigen::Quaterniond q(n(rng), n(rng), n(rng), n(rng));
  return q.normalized().toRotationMatrix();
}

Eigen::Matrix4d randomRigid(std::mt19937& rng, double maxTranslate) {
  std::uniform_real_distribution<double> u(-maxTranslate, maxTranslate);
  Eigen::Matrix4d m = Eigen::Matrix4d::Identity();
  m.topLeftCorner<3, 3>() = randomRotation(rng);
  m.block<3, 1>(0, 3) = Eigen::Vector3d(u(rng), u(rng), u(rng));
  return m;
}

// Points of the unit-ish hyperboloid of one sheet x² + y² − z² = 1 (parametric).
std::vector<Eigen::Vector3d> hyperboloidPoints(std::mt19937& rng, int n) {
  std::uniform_real_distribution<double> t(0, 2 * M_PI), s(-2, 2);
  std::vector<Eigen::Vector3d> pts;
  for (int i = 0; i < n; ++i) {
    const double a = t(rng), v = s(rng);
    pts.emplace_back(std::cosh(v) * std::cos(a), std::cosh(v) * std::sin(a), std::sinh(v));
  }
  return pts;
}

double relativeResidual(const Quadric& q, const Eigen::Vector3d& p) {
  const Eigen::Vector4d X = p.homogeneous();
  return std::abs(q.evalHomogeneous(X)) / (q.Q.cwiseAbs().maxCoeff() * X.squaredNorm());
}

}  // namespace

TEST(QuadricTransform, AffineKeepsSurfacePointsOnSurface) {
  std::mt19937 rng(1);
  const Quadric q = makeHyperboloid1({1, 1, 1}, 4).quadric;
  std::uniform_real_distribution<double> u(-2, 2);
  for (int trial = 0; trial < 50; ++trial) {
    Eigen::Matrix4d M = Eigen::Matrix4d::Identity();
    for (int r = 0; r < 3; ++r)
      for (int c = 0; c < 4; ++c) M(r, c) = u(rng);
    if (std::abs(M.topLeftCorner<3, 3>().determinant()) < 0.1) continue;
    const Quadric q2 = q.transformed(M);
    for (const auto& p : hyperboloidPoints(rng, 20)) {
      ASSERT_LT(relativeResidual(q, p), 1e-12);
      const Eigen::Vector3d p2 = (M * p.homogeneous()).hnormalized();
      EXPECT_LT(relativeResidual(q2, p2), 1e-9) << "trial " << trial;
    }
  }
}

TEST(QuadricTransform, PerspectiveKeepsSurfacePointsOnSurface) {
  std::mt19937 rng(2);
  const Quadric q = makeHyperboloid1({1, 1, 1}, 4).quadric;
  std::uniform_real_distribution<double> u(-1, 1);
  for (int trial = 0; trial < 50; ++trial) {
    Camera cam;
    cam.eye = {8 + 4 * u(rng), 6 * u(rng), 10 + 4 * u(rng)};
    cam.target = {u(rng), u(rng), u(rng)};
    cam.fov_y_deg = 30 + 20 * (u(rng) + 1);
    const Eigen::Matrix4d M = cam.worldToWindow(640, 480);
    const Quadric q2 = q.transformed(M);
    for (const auto& p : hyperboloidPoints(rng, 20)) {
      const Eigen::Vector4d X = M * p.homogeneous();
      if (std::abs(X[3]) < 1e-3) continue;
      // Compare with the surface's own scale: the residual relative to |Q'| |X'|².
      EXPECT_LT(relativeResidual(q2, X.hnormalized()), 1e-8) << "trial " << trial;
    }
  }
  // And a general projective map with a non-trivial last row.
  Eigen::Matrix4d P;
  P << 1, 0.2, 0, 0.5, 0, 1, 0.3, 0, 0.1, 0, 1, 0, 0.05, 0.02, 0.1, 1;
  const Quadric q3 = q.transformed(P);
  for (const auto& p : hyperboloidPoints(rng, 100)) {
    const Eigen::Vector4d X = P * p.homogeneous();
    if (std::abs(X[3]) < 1e-2) continue;
    EXPECT_LT(relativeResidual(q3, X.hnormalized()), 1e-9);
  }
}

TEST(QuadricTransform, WrongFormulaWouldFail) {
  // Guard: transforming with M⁻¹ instead of M moves points off the surface.
  const Quadric q = makeSphere({0, 0, 0}, 1).quadric;
  Eigen::Matrix4d M = Eigen::Matrix4d::Identity();
  M(0, 3) = 2;
  const Quadric wrong = q.transformed(M.inverse());
  EXPECT_GT(std::abs(wrong.eval({3, 0, 0})), 1.0);
  EXPECT_NEAR(q.transformed(M).eval({3, 0, 0}), 0.0, 1e-12);
}

struct TypeCase {
  const char* name;
  Primitive prim;
  QuadricType type;
};

TEST(QuadricType, ConstructorsAreClassifiedInvariantly) {
  const std::vector<TypeCase> cases = {
      {"sphere", makeSphere({1, 2, 3}, 0.7), QuadricType::Ellipsoid},
      {"ellipsoid", makeEllipsoid({0, 0, 0}, {1, 2, 3}), QuadricType::Ellipsoid},
      {"cylinder", makeCylinder({0, 0, 0}, {1, 1, 1}, 0.5), QuadricType::EllipticCylinder},
      {"cone", makeCone({1, 0, 0}, {1, 2, 0}, 0.5), QuadricType::EllipticCone},
      {"paraboloid", makeParaboloid(1, 2, 3), QuadricType::EllipticParaboloid},
      {"hyperboloid1", makeHyperboloid1({1, 2, 1}, 2), QuadricType::HyperboloidOneSheet},
      {"hyperboloid2", makeHyperboloid2({1, 2, 1}, 2), QuadricType::HyperboloidTwoSheets},
      {"hyperbolic paraboloid", makeHyperbolicParaboloid(1, 2, 3), QuadricType::HyperbolicParaboloid},
      {"elliptic cylinder", makeEllipticCylinder(1, 2, 3), QuadricType::EllipticCylinder},
      {"hyperbolic cylinder", makeHyperbolicCylinder(1, 2, 3, 4), QuadricType::HyperbolicCylinder},
      {"parabolic cylinder", makeParabolicCylinder(0.5, 3, 4), QuadricType::ParabolicCylinder},
      {"plane", makePlane({1, 2, 3}, {0, 1, 1}), QuadricType::Plane},
      {"triangle", makeTriangle({0, 0, 0}, {1, 0, 0}, {0, 1, 0}), QuadricType::Plane},
  };
  std::mt19937 rng(3);
  for (const auto& c : cases) {
    EXPECT_EQ(quadricType(c.prim.quadric), c.type) << c.name;
    for (double k : {1e-12, -1.0, 3.5, -7e9})
      EXPECT_EQ(quadricType(Quadric(Eigen::Matrix4d(k * c.prim.quadric.Q))), c.type) << c.name << " k=" << k;
    for (int trial = 0; trial < 20; ++trial) {
      const Eigen::Matrix4d R = randomRigid(rng, trial < 10 ? 5.0 : 200.0);
      EXPECT_EQ(quadricType(c.prim.quadric.transformed(R)), c.type) << c.name << " trial " << trial;
    }
  }
}

TEST(QuadricType, DegenerateTypes) {
  using T = QuadricType;
  auto diag = [](double a, double b, double c, double j) {
    return Quadric::fromCoefficients(a, b, c, 0, 0, 0, 0, 0, 0, j);
  };
  EXPECT_EQ(quadricType(diag(1, -1, 0, 0)), T::IntersectingPlanes);
  EXPECT_EQ(quadricType(diag(1, 0, 0, -1)), T::ParallelPlanes);
  EXPECT_EQ(quadricType(diag(1, 0, 0, 0)), T::CoincidentPlanes);
  EXPECT_EQ(quadricType(diag(1, 1, 0, 0)), T::Line);
  EXPECT_EQ(quadricType(diag(1, 1, 1, 0)), T::Point);
  EXPECT_EQ(quadricType(diag(1, 1, 1, 1)), T::ImaginaryEllipsoid);
  EXPECT_EQ(quadricType(diag(1, 1, 0, 1)), T::ImaginaryEllipticCylinder);
  EXPECT_EQ(quadricType(diag(1, 0, 0, 1)), T::ImaginaryParallelPlanes);
  EXPECT_EQ(quadricType(diag(0, 0, 0, 1)), T::Empty);
  EXPECT_EQ(quadricType(diag(0, 0, 0, 0)), T::All);
  // A cone moved far away keeps its apex (J' = 0 after completing the square).
  std::mt19937 rng(4);
  const Quadric cone = diag(1, 1, -0.25, 0);
  for (int i = 0; i < 20; ++i) EXPECT_EQ(quadricType(cone.transformed(randomRigid(rng, 1000))), T::EllipticCone);
  // And a slightly different one is a hyperboloid, not a cone.
  EXPECT_EQ(quadricType(diag(1, 1, -0.25, -1e-3)), T::HyperboloidOneSheet);
  EXPECT_EQ(quadricType(diag(1, 1, -0.25, 1e-3)), T::HyperboloidTwoSheets);
}

TEST(StableRoots, AccurateWhereTheNaiveFormulaLosesDigits) {
  // a z² + 2 b z + c with b² ≫ a c: the small root suffers cancellation in (−b + √Δ) / a.
  const double a = 1, b = -1e8, c = 1;
  const long double bl = b, dl = std::sqrt((long double)b * b - (long double)a * c);
  const long double small = (long double)c / (-bl + dl), large = (-bl + dl) / a;
  const QuadraticRoots r = stableRoots(a, b, c);
  ASSERT_EQ(r.count, 2);
  EXPECT_LT(std::abs((r.r[0] - small) / small), 1e-15);
  EXPECT_LT(std::abs((r.r[1] - large) / large), 1e-15);
  const double naive = (-b - std::sqrt(b * b - a * c)) / a;
  EXPECT_GT(std::abs((naive - small) / small), 1e-3);  // the naive form is far off
}

TEST(StableRoots, DegenerateCases) {
  QuadraticRoots r = stableRoots(0, 1, -4);  // 2z − 4 = 0
  ASSERT_EQ(r.count, 1);
  EXPECT_DOUBLE_EQ(r.r[0], 2);
  r = stableRoots(1, 0, 1);  // z² + 1
  EXPECT_EQ(r.count, 0);
  r = stableRoots(1, 0, 0);  // z² = 0
  ASSERT_EQ(r.count, 1);
  EXPECT_EQ(r.r[0], 0);
  r = stableRoots(2, -3, 4);  // 2z² − 6z + 4 = 0 → 1, 2
  ASSERT_EQ(r.count, 2);
  EXPECT_DOUBLE_EQ(r.r[0], 1);
  EXPECT_DOUBLE_EQ(r.r[1], 2);
  r = stableRoots(0, 0, 1);
  EXPECT_EQ(r.count, 0);
}

TEST(HalfSpace, SignConventionAndOwnership) {
  const HalfSpace h(Eigen::Vector4d(0, 0, 1, -1));  // z <= 1
  EXPECT_TRUE(h.contains({0, 0, 0}));
  EXPECT_FALSE(h.contains({0, 0, 2}));
  const HalfSpace o = h.opposite();
  EXPECT_FALSE(o.contains({0, 0, 0}));
  EXPECT_TRUE(o.contains({0, 0, 2}));
  // A point on the plane belongs to exactly one side.
  for (const Eigen::Vector3d& p : {Eigen::Vector3d(0, 0, 1), Eigen::Vector3d(5, -3, 1)})
    EXPECT_NE(h.contains(p), o.contains(p));
  // Ownership survives transforms.
  Eigen::Matrix4d M = Eigen::Matrix4d::Identity();
  M(2, 3) = 3;
  EXPECT_EQ(h.transformedByInverse(M.inverse()).owns_boundary, h.owns_boundary);
}
