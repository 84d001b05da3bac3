// Bernstein-Bézier quadric patches: conversion (3.15)/(3.16), the corrected sphere
// example, evaluation, the empty-cell test, G0/G1 joins (3.23) and crack-free clipping.
#include <gtest/gtest.h>

#include <random>

#include "modeling/modelers/bb_quadric.h"

using namespace qacc;
using Eigen::Matrix4d;
using Eigen::Vector3d;
using Eigen::Vector4d;

namespace {

Tetrahedron unitTet() { return {Vector3d(0, 0, 0), Vector3d(1, 0, 0), Vector3d(0, 1, 0), Vector3d(0, 0, 1)}; }

Quadric randomQuadric(std::mt19937& rng) {
  std::uniform_real_distribution<double> u(-1, 1);
  Matrix4d m;
  for (int i = 0; i < 4; ++i)
    for (int j = 0; j < 4; ++j) m(i, j) = u(rng);
  return Quadric(m);
}

Tetrahedron randomTet(std::mt19937& rng) {
  std::uniform_real_distribution<double> u(-2, 2);
  Tetrahedron t;
  do {
    for (auto& v : t) v = Vector3d(u(rng), u(rng), u(rng));
  } while (std::abs(BBQuadric::signedVolume(t)) < 0.05);
  return t;
}

}  // namespace

TEST(BBQuadric, CorrectedSphereExample) {
  const Quadric sphere = Quadric::fromCoefficients(1, 1, 1, 0, 0, 0, 0, 0, 0, -1);
  const BBQuadric bb = BBQuadric::fromQuadric(sphere, unitTet());
  Matrix4d expected;
  expected << -1, -1, -1, -1, -1, 0, -1, -1, -1, -1, 0, -1, -1, -1, -1, 0;
  EXPECT_LT((bb.C - expected).cwiseAbs().maxCoeff(), 1e-15) << bb.C;
  // Vertex coefficients are f(Va); named coefficients follow the documented layout.
  for (int a = 0; a < 4; ++a) EXPECT_DOUBLE_EQ(bb.C(a, a), sphere.eval(bb.V[a]));
  EXPECT_DOUBLE_EQ(bb.coefficient(2, 0, 0, 0), -1.0);
  EXPECT_DOUBLE_EQ(bb.coefficient(0, 2, 0, 0), 0.0);
  EXPECT_DOUBLE_EQ(bb.coefficient(0, 1, 1, 0), -1.0);
  // Going back gives the sphere exactly.
  EXPECT_LT((bb.toQuadric().Q - sphere.Q).cwiseAbs().maxCoeff(), 1e-14);
}

TEST(BBQuadric, RoundTripAndEvaluation) {
  std::mt19937 rng(5);
  std::uniform_real_distribution<double> u(0, 1);
  for (int trial = 0; trial < 50; ++trial) {
    const Quadric q = randomQuadric(rng);
    const Tetrahedron t = randomTet(rng);
    const BBQuadric bb = BBQuadric::fromQuadric(q, t);
    EXPECT_LT((bb.toQuadric().Q - q.Q).cwiseAbs().maxCoeff(), 1e-9);
    // C → Q → C as well.
    const BBQuadric back = BBQuadric::fromQuadric(bb.toQuadric(), t);
    EXPECT_LT((back.C - bb.C).cwiseAbs().maxCoeff(), 1e-9);
    // The BB sum (3.14), written out term by term, equals the Cartesian value.
    Vector4d l(u(rng), u(rng), u(rng), u(rng));
    l /= l.sum();
    double sum = 0;
    for (const auto& m : BBQuadric::multiIndices()) {
      double fact = 1, mono = 1;
      for (int a = 0; a < 4; ++a) {
        fact *= (m[a] == 2 ? 2.0 : 1.0);
        mono *= std::pow(l[a], m[a]);
      }
      sum += 2.0 / fact * bb.coefficient(m[0], m[1], m[2], m[3]) * mono;
    }
    const Vector3d p = bb.point(l);
    EXPECT_NEAR(sum, q.eval(p), 1e-10);
    EXPECT_NEAR(bb.evalBarycentric(l), q.eval(p), 1e-10);
    EXPECT_LT((bb.barycentric(p) - l).norm(), 1e-10);
  }
}

TEST(BBQuadric, SetCoefficientLayoutAndBadIndices) {
  BBQuadric bb(unitTet(), Matrix4d::Zero());
  bb.setCoefficient(0, 1, 0, 1, 3.5);
  EXPECT_EQ(bb.C(1, 3), 3.5);
  EXPECT_EQ(bb.C(3, 1), 3.5);
  bb.setCoefficient(0, 0, 2, 0, -2);
  EXPECT_EQ(bb.C(2, 2), -2);
  EXPECT_THROW(bb.coefficient(1, 1, 1, 0), std::invalid_argument);
  EXPECT_THROW(bb.coefficient(3, -1, 0, 0), std::invalid_argument);
}

TEST(BBQuadric, InterpolationAndTangencyProperties) {
  // C(0,0) = 0 ⇒ the surface passes through V0; C(0,1) = 0 too ⇒ tangent to edge V0V1 there.
  std::mt19937 rng(7);
  std::uniform_real_distribution<double> u(-1, 1);
  for (int trial = 0; trial < 20; ++trial) {
    const Tetrahedron t = randomTet(rng);
    Matrix4d c;
    for (int i = 0; i < 4; ++i)
      for (int j = 0; j < 4; ++j) c(i, j) = u(rng);
    BBQuadric bb(t, c);
    bb.setCoefficient(2, 0, 0, 0, 0);
    bb.setCoefficient(1, 1, 0, 0, 0);
    const Quadric q = bb.toQuadric();
    EXPECT_NEAR(q.eval(t[0]), 0, 1e-10);
    const Vector3d g = q.gradient(t[0]);
    EXPECT_NEAR(g.normalized().dot((t[1] - t[0]).normalized()), 0, 1e-9);
    // But not tangent to the other edges in general.
    EXPECT_GT(std::abs(g.normalized().dot((t[2] - t[0]).normalized())), 1e-6);
  }
}

TEST(BBQuadric, StrictSignEmptyTest) {
  const Quadric sphere = Quadric::fromCoefficients(1, 1, 1, 0, 0, 0, 0, 0, 0, -1);
  // A tetrahedron far from the sphere: every coefficient positive.
  Tetrahedron far = {Vector3d(3, 3, 3), Vector3d(4, 3, 3), Vector3d(3, 4, 3), Vector3d(3, 3, 4)};
  EXPECT_TRUE(BBQuadric::fromQuadric(sphere, far).isProvablyEmpty());
  // A tetrahedron inside: every coefficient negative.
  Tetrahedron in = {Vector3d(0, 0, 0), Vector3d(.3, 0, 0), Vector3d(0, .3, 0), Vector3d(0, 0, .3)};
  EXPECT_TRUE(BBQuadric::fromQuadric(sphere, in).isProvablyEmpty());
  // The unit tetrahedron is crossed by the sphere (vertices on it): not empty.
  EXPECT_FALSE(BBQuadric::fromQuadric(sphere, unitTet()).isProvablyEmpty());
  // Brute-force check of soundness: whenever the test says empty, no sign change inside.
  std::mt19937 rng(3);
  std::uniform_real_distribution<double> u(0, 1);
  int empties = 0;
  for (int trial = 0; trial < 300; ++trial) {
    Tetrahedron t = randomTet(rng);
    const Vector3d shift(u(rng) * 4 - 2, u(rng) * 4 - 2, u(rng) * 4 - 2);
    for (auto& v : t) v = 0.3 * v + shift;
    const BBQuadric bb = BBQuadric::fromQuadric(sphere, t);
    if (!bb.isProvablyEmpty()) continue;
    ++empties;
    const double s = bb.C(0, 0) > 0 ? 1 : -1;
    for (int k = 0; k < 200; ++k) {
      Vector4d l(u(rng), u(rng), u(rng), u(rng));
      l /= l.sum();
      EXPECT_GT(s * bb.evalBarycentric(l), 0);
    }
  }
  EXPECT_GT(empties, 10);
}

TEST(BBQuadric, G0AndG1JoinsAcrossASharedFace) {
  std::mt19937 rng(11);
  std::uniform_real_distribution<double> u(-1, 1);
  double worst_g1_angle = 0, worst_g0_angle = 0;
  for (int trial = 0; trial < 30; ++trial) {
    const Tetrahedron t = randomTet(rng);
    // Neighbour on the other side of face (V0, V1, V2), listed in another order.
    const Vector3d centroid = (t[0] + t[1] + t[2]) / 3.0;
    const Vector3d apex = centroid + (centroid - t[3]) * 0.7 + Vector3d(u(rng), u(rng), u(rng)) * 0.2;
    const Tetrahedron n = {t[2], apex, t[0], t[1]};
    Matrix4d c1, c2;
    for (int i = 0; i < 4; ++i)
      for (int j = 0; j < 4; ++j) c1(i, j) = u(rng), c2(i, j) = u(rng);
    const BBQuadric p(t, c1);
    BBQuadric g0(n, c2), g1(n, c2);
    joinG0(p, g0);
    joinG1(p, g1);
    const Quadric qp = p.toQuadric(), q0 = g0.toQuadric(), q1 = g1.toQuadric();
    const FaceContinuity c0 = measureFaceContinuity(qp, q0, t[0], t[1], t[2]);
    const FaceContinuity cg1 = measureFaceContinuity(qp, q1, t[0], t[1], t[2]);
    EXPECT_LT(c0.max_value_diff, 1e-9);
    EXPECT_LT(cg1.max_value_diff, 1e-9);
    worst_g1_angle = std::max(worst_g1_angle, cg1.max_angle_face_deg);
    worst_g0_angle = std::max(worst_g0_angle, c0.max_angle_face_deg);
    // G1 leaves the free-vertex coefficient alone and fixes the rest as (3.23) says.
    EXPECT_EQ(g1.C(1, 1), c2(1, 1));
    const Vector4d lam = p.barycentric(apex);
    EXPECT_NEAR(g1.C(1, 2), p.C.row(0).dot(lam), 1e-12);
  }
  EXPECT_LT(worst_g1_angle, 1e-5);
  EXPECT_GT(worst_g0_angle, 1.0);  // random G0 joins do have a crease
}

TEST(BBQuadric, SharedFaceIsOnePlaneAndItsOpposite) {
  const Tetrahedron t = {Vector3d(0.1, 0.2, 0.3), Vector3d(1.3, 0.1, -0.2), Vector3d(0.2, 1.1, 0.4), Vector3d(0.3, 0.2, 1.7)};
  const Tetrahedron n = {t[1], Vector3d(1, 1, -1), t[0], t[2]};
  const BBQuadric a(t, Matrix4d::Identity()), b(n, Matrix4d::Identity());
  const HalfSpace ha = a.faceHalfSpace(3);  // face V0V1V2 of a
  const HalfSpace hb = b.faceHalfSpace(1);  // the same face in b
  EXPECT_EQ(ha.p, Vector4d(-hb.p));
  EXPECT_NE(ha.owns_boundary, hb.owns_boundary);
  // Every tested point (on the plane included) is kept by exactly one of the two.
  std::mt19937 rng(1);
  std::uniform_real_distribution<double> u(0, 1);
  for (int k = 0; k < 1000; ++k) {
    const double s = u(rng), r = u(rng) * (1 - s);
    const Vector3d onFace = t[0] + s * (t[1] - t[0]) + r * (t[2] - t[0]);
    const double va = ha.eval(onFace), vb = hb.eval(onFace);
    EXPECT_NE(ha.keeps(va), hb.keeps(vb));
  }
  // Each half-space keeps its own tetrahedron's free vertex.
  EXPECT_TRUE(ha.contains(t[3]));
  EXPECT_TRUE(hb.contains(n[1]));
  const Primitive prim = a.toPrimitive(2, 7, true);
  EXPECT_EQ(prim.clip.size(), 4u);
  EXPECT_EQ(prim.material, 2);
  EXPECT_EQ(prim.object, 7);
  const Vector3d inside = (t[0] + t[1] + t[2] + t[3]) / 4.0;
  for (const auto& h : prim.clip) EXPECT_TRUE(h.contains(inside));
}
