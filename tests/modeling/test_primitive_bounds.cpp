// World bounds of clipped quadric pieces (modeling/geometry/primitive_bounds.h) against a
// brute-force extent: every point of the piece lies in the bounds, and the bounds are within
// 1 % of the sampled extent. A piece is unbounded only when it is.
#include <gtest/gtest.h>

#include <random>

#include "modeling/geometry/natural_quadrics.h"
#include "modeling/geometry/primitive_bounds.h"
#include "modeling/geometry/stable_roots.h"
#include "tests/sanitized_build.h"

using namespace qacc;

namespace {

bool inside(const Primitive& p, const Eigen::Vector3d& x) {
  for (const auto& h : p.clip)
    if (h.p.dot(x.homogeneous()) > 1e-9 * (h.p.head<3>().norm() * x.norm() + std::abs(h.p[3]))) return false;
  return true;
}

// The sampled extent of the piece: points where lines parallel to each axis, on an n x n
// grid over `box`, meet the surface inside the clip polyhedron; for a solid also where they
// enter or leave the polyhedron inside f <= 0.
Eigen::AlignedBox3d sampledExtent(const Primitive& p, const Eigen::AlignedBox3d& box, int n) {
  Eigen::AlignedBox3d out;
  const Eigen::Matrix4d& Q = p.quadric.Q;
  for (int ax = 0; ax < 3; ++ax) {
    const int a1 = (ax + 1) % 3, a2 = (ax + 2) % 3;
    for (int i = 0; i <= n; ++i)
      for (int j = 0; j <= n; ++j) {
        Eigen::Vector3d o = box.min();
        o[a1] += box.sizes()[a1] * i / n;
        o[a2] += box.sizes()[a2] * j / n;
        const Eigen::Vector4d H = o.homogeneous();
        Eigen::Vector4d D = Eigen::Vector4d::Zero();
        D[ax] = 1;
        const QuadraticRoots r = stableRoots(D.dot(Q * D), D.dot(Q * H), H.dot(Q * H));
        for (int k = 0; k < r.count; ++k) {
          const Eigen::Vector3d x = o + r.r[k] * D.head<3>();
          if (x.allFinite() && inside(p, x)) out.extend(x);
        }
        if (!p.solid) continue;
        for (const auto& h : p.clip) {
          const double den = h.p.dot(D);
          if (den == 0) continue;
          const Eigen::Vector3d x = o - (h.p.dot(H) / den) * D.head<3>();
          if (x.allFinite() && inside(p, x) && x.homogeneous().dot(Q * x.homogeneous()) <= 0) out.extend(x);
        }
      }
  }
  return out;
}

Primitive randomPiece(std::mt19937& rng, int kind) {
  std::uniform_real_distribution<double> u(-1, 1), s(0.4, 1.6);
  Primitive p;
  switch (kind % 9) {
    case 0: p = makeEllipsoid({0, 0, 0}, {s(rng), s(rng), s(rng)}); break;
    case 1: p = makeCylinder({0, 0, -1}, {0, 0, 1}, s(rng)); break;
    case 2: p = makeCone({0, 0, 0}, {0, 0, 1.5}, s(rng)); break;
    case 3: p = makeParaboloid(s(rng), s(rng), 2 * s(rng)); break;
    case 4: p = makeHyperboloid1({s(rng), s(rng), s(rng)}, 2 * s(rng)); break;
    case 5: p = makeHyperboloid2({s(rng), s(rng), s(rng)}, 3 * s(rng)); break;
    case 6: p = makeHyperbolicParaboloid(s(rng), s(rng), s(rng)); break;
    case 7: p = makeHyperbolicCylinder(0.5 * s(rng), s(rng), s(rng), 2 * s(rng)); break;
    default: p = makeParabolicCylinder(0.3 * s(rng), s(rng), 2 * s(rng)); break;
  }
  // One more plane through a point near the centre, a random rotation and translation.
  const Eigen::Vector3d n = Eigen::Vector3d(u(rng), u(rng), u(rng)).normalized();
  p.clip.push_back(HalfSpace(Eigen::Vector4d(n.x(), n.y(), n.z(), 0.3 * u(rng))));
  p.solid = kind % 2 == 1;
  Eigen::Affine3d T = Eigen::Affine3d::Identity();
  T.translate(Eigen::Vector3d(20 * u(rng), 20 * u(rng), 20 * u(rng)));
  T.rotate(Eigen::AngleAxisd(M_PI * u(rng), Eigen::Vector3d(u(rng), u(rng), u(rng)).normalized()));
  return p.transformed(T.matrix());
}

}  // namespace

TEST(PrimitiveBounds, ContainEveryPointOfThePieceAndAreWithinOnePercent) {
  std::mt19937 rng(20261123);
  int checked = 0, unbounded = 0;
  // Under the sanitizers the first 18 of the same random pieces: each of the nine kinds as a
  // surface and as a solid (tests/sanitized_build.h).
  const int trials = kSanitizedBuild ? 18 : 90;
  for (int trial = 0; trial < trials; ++trial) {
    const Primitive p = randomPiece(rng, trial);
    const PrimitiveBounds b = primitiveBounds(p);
    if (b.empty) continue;
    if (!b.bounded) {
      // Only a solid can be left open here (the clip planes bound every surface piece);
      // the cases below check open pieces against known ones.
      EXPECT_TRUE(p.solid) << "trial " << trial << ": a surface piece said unbounded";
      ++unbounded;
      continue;
    }
    Eigen::AlignedBox3d search = b.box;
    search.extend(Eigen::Vector3d(b.box.min() - 0.25 * b.box.sizes()));
    search.extend(Eigen::Vector3d(b.box.max() + 0.25 * b.box.sizes()));
    const Eigen::AlignedBox3d sampled = sampledExtent(p, search, 400);
    if (sampled.isEmpty()) continue;
    ++checked;
    const double tol = 1e-9 * (b.box.sizes().norm() + b.box.center().norm());
    for (int a = 0; a < 3; ++a) {
      EXPECT_LE(b.box.min()[a], sampled.min()[a] + tol) << "trial " << trial << " axis " << a << ": a point below";
      EXPECT_GE(b.box.max()[a], sampled.max()[a] - tol) << "trial " << trial << " axis " << a << ": a point above";
      const double slack = 0.01 * b.box.sizes().maxCoeff();
      EXPECT_GE(b.box.min()[a], sampled.min()[a] - slack) << "trial " << trial << " axis " << a << ": loose below";
      EXPECT_LE(b.box.max()[a], sampled.max()[a] + slack) << "trial " << trial << " axis " << a << ": loose above";
    }
  }
  EXPECT_GE(checked, 2 * trials / 3);
  EXPECT_LE(unbounded, 2 * trials / 9);
}

TEST(PrimitiveBounds, UnboundedOnlyWhenThePieceIs) {
  // A hyperboloid of one sheet clipped to a slab is bounded; without the slab it is not;
  // a solid paraboloid cut by a plane across its axis is bounded, along its axis it is not.
  Primitive h = makeHyperboloid1({0.6, 0.6, 0.75}, 2.0);
  EXPECT_TRUE(primitiveBounds(h).bounded);
  h.clip.clear();
  EXPECT_FALSE(primitiveBounds(h).bounded);
  Primitive par = makeParaboloid(1.0, 1.0, 2.0);
  par.solid = true;
  EXPECT_TRUE(primitiveBounds(par).bounded);
  par.clip = {HalfSpace(Eigen::Vector4d(1, 0, 0, 0))};  // x <= 0: the cup still opens upward
  EXPECT_FALSE(primitiveBounds(par).bounded);
  // A triangle (a plane clipped by its edges) is bounded, with its vertices as bounds.
  const Primitive t = makeTriangle({0, 0, 0}, {2, 0, 0}, {0, 3, 1});
  const PrimitiveBounds tb = primitiveBounds(t);
  ASSERT_TRUE(tb.bounded);
  EXPECT_NEAR(tb.box.max().x(), 2, 1e-6);
  EXPECT_NEAR(tb.box.max().y(), 3, 1e-6);
  EXPECT_NEAR(tb.box.max().z(), 1, 1e-6);
  EXPECT_NEAR(tb.box.min().x(), 0, 1e-6);
  // A solid saddle clipped only at its sides is open upward; capped, it is closed.
  Primitive saddle = makeHyperbolicParaboloid(1.0, 1.0, 1.0);
  saddle.solid = true;
  EXPECT_FALSE(primitiveBounds(saddle).bounded);
  saddle.clip.push_back(HalfSpace(Eigen::Vector4d(0, 0, 1, -3)));  // z <= 3
  EXPECT_TRUE(primitiveBounds(saddle).bounded);
  // An empty piece: a sphere cut away entirely.
  Primitive e = makeSphere({0, 0, 0}, 1.0);
  e.clip = {HalfSpace(Eigen::Vector4d(-1, 0, 0, 2))};  // x >= 2
  EXPECT_TRUE(primitiveBounds(e).empty);
}

// Unclipped ellipsoids take a closed form (an atom, a sphere of a large scene): it must agree
// with the general path (the same ellipsoid behind a plane that cuts nothing), contain every
// sampled point, and call an ellipsoid with no real point empty.
TEST(PrimitiveBounds, UnclippedEllipsoidsInClosedFormAgreeWithTheGeneralPath) {
  std::mt19937 rng(7);
  std::uniform_real_distribution<double> u(-1, 1), s(0.2, 3);
  for (int i = 0; i < 200; ++i) {
    Primitive p = makeEllipsoid({0, 0, 0}, {s(rng), s(rng), s(rng)});
    p.solid = i % 2 == 1;
    Eigen::Affine3d T = Eigen::Affine3d::Identity();
    T.translate(Eigen::Vector3d(50 * u(rng), 50 * u(rng), 50 * u(rng)));
    T.rotate(Eigen::AngleAxisd(M_PI * u(rng), Eigen::Vector3d(u(rng), u(rng), u(rng)).normalized()));
    p = p.transformed(T.matrix());
    if (i % 3 == 0) p.quadric.Q = -p.quadric.Q;  // the same surface, the solid's outside
    Primitive general = p;
    general.clip.push_back(HalfSpace(Eigen::Vector4d(1, 0, 0, -1e4)));  // x <= 1e4: cuts nothing
    const PrimitiveBounds a = primitiveBounds(p), b = primitiveBounds(general);
    ASSERT_EQ(a.bounded, b.bounded) << i;
    ASSERT_EQ(a.empty, b.empty) << i;
    if (!a.bounded) continue;
    const double tol = 1e-7 * (1 + b.box.sizes().norm());
    EXPECT_LT((a.box.min() - b.box.min()).cwiseAbs().maxCoeff(), tol) << i;
    EXPECT_LT((a.box.max() - b.box.max()).cwiseAbs().maxCoeff(), tol) << i;
    const Eigen::AlignedBox3d sampled = sampledExtent(p, b.box, 40);
    EXPECT_TRUE(a.box.contains(sampled)) << i;
  }
  Primitive none = makeEllipsoid({0, 0, 0}, {1, 1, 1});
  none.quadric.Q(3, 3) = 1;  // x² + y² + z² + 1 = 0
  EXPECT_TRUE(primitiveBounds(none).empty);
}
