// Degree reduction of algebraic surfaces (issue 6): polynomial parsing, BB change of basis,
// iterated Petersen reduction vs the closed formulas (5.5) and the vertex/edge rule, Kuhn
// split conformity, Bey refinement, G0 between cells, culling, merging, error vs level.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <map>
#include <random>
#include <set>

#include "modeling/algebraic/bb_tetra.h"
#include "modeling/algebraic/degree_reduction.h"
#include "modeling/algebraic/kuhn_mesh.h"
#include "modeling/algebraic/polynomial3.h"

using namespace qacc;
using Eigen::Vector3d;
using Eigen::Vector4d;

namespace {

Tetrahedron randomTet(std::mt19937& rng) {
  std::uniform_real_distribution<double> u(-1.0, 1.0);
  for (;;) {
    Tetrahedron t;
    for (auto& v : t) v = Vector3d(u(rng), u(rng), u(rng));
    if (std::fabs(BBQuadric::signedVolume(t)) > 0.05) return t;
  }
}

Vector4d randomBary(std::mt19937& rng) {
  std::uniform_real_distribution<double> u(0.0, 1.0);
  Vector4d l(u(rng), u(rng), u(rng), u(rng));
  return l / l.sum();
}

Polynomial3 randomPolynomial(std::mt19937& rng, int degree) {
  std::uniform_real_distribution<double> u(-1.0, 1.0);
  Polynomial3 p;
  for (int i = 0; i <= degree; ++i)
    for (int j = 0; i + j <= degree; ++j)
      for (int k = 0; i + j + k <= degree; ++k) p = p + Polynomial3::monomial(i, j, k, u(rng));
  return p;
}

double maxAbsDiff(const BBTetra& a, const BBTetra& b) {
  EXPECT_EQ(a.degree(), b.degree());
  double m = 0;
  for (std::size_t i = 0; i < a.coefficients().size(); ++i)
    m = std::max(m, std::fabs(a.coefficients()[i] - b.coefficients()[i]));
  return m;
}

const char* kTorus = "(x^2+y^2+z^2+R^2-r^2)^2 - 4 R^2 (x^2+y^2)";

}  // namespace

TEST(Polynomial3, ParsesAndEvaluates) {
  const Polynomial3 q = Polynomial3::parse("x^4 + y^4 + z^4 - 1");
  EXPECT_EQ(q.degree(), 4);
  const Vector3d p(0.3, -0.7, 1.1);
  EXPECT_NEAR(q.eval(p), std::pow(0.3, 4) + std::pow(0.7, 4) + std::pow(1.1, 4) - 1, 1e-14);
  const Polynomial3 t = Polynomial3::parse(kTorus, {{"R", 1.0}, {"r", 0.4}});
  EXPECT_EQ(t.degree(), 4);
  const double s = p.squaredNorm() + 1.0 - 0.16;
  EXPECT_NEAR(t.eval(p), s * s - 4.0 * (p.x() * p.x() + p.y() * p.y()), 1e-13);
  // Implicit multiplication, unary signs, decimals and exponents.
  const Polynomial3 m = Polynomial3::parse("2x y - -3.5e-1 z^2 + (x - 1)(x + 1)");
  EXPECT_NEAR(m.eval(p), 2 * 0.3 * -0.7 + 0.35 * 1.21 + (0.09 - 1), 1e-14);
  EXPECT_NEAR(Polynomial3::parse("0x + 1").eval(p), 1.0, 0.0);
  EXPECT_NEAR(Polynomial3::parse("-x^2").eval(p), -0.09, 1e-15);
}

TEST(Polynomial3, GradientMatchesFiniteDifferences) {
  std::mt19937 rng(3);
  const Polynomial3 f = randomPolynomial(rng, 5);
  const Vector3d p(0.2, -0.4, 0.6);
  const Vector3d g = f.gradient(p);
  for (int a = 0; a < 3; ++a) {
    Vector3d e = Vector3d::Zero();
    e[a] = 1e-6;
    EXPECT_NEAR(g[a], (f.eval(p + e) - f.eval(p - e)) / 2e-6, 1e-7);
    EXPECT_NEAR(f.derivative(a).eval(p), g[a], 1e-12);
  }
  // Restriction to a line matches evaluation.
  const Vector3d d(0.3, 0.1, -0.5);
  const auto c = f.alongLine(p, d);
  for (double t : {-1.0, 0.25, 2.0}) {
    double v = 0;
    for (std::size_t m = c.size(); m-- > 0;) v = v * t + c[m];
    EXPECT_NEAR(v, f.eval(p + t * d), 1e-11);
  }
}

TEST(Polynomial3, ParseErrorsNameThePosition) {
  auto message = [](const std::string& s) {
    try {
      Polynomial3::parse(s);
    } catch (const PolynomialParseError& e) {
      return std::string(e.what());
    }
    return std::string("no error");
  };
  EXPECT_NE(message("x^").find("position 3"), std::string::npos) << message("x^");
  EXPECT_NE(message("x + w").find("unknown name 'w'"), std::string::npos);
  EXPECT_NE(message("(x + 1").find("expected ')'"), std::string::npos);
  EXPECT_NE(message("x * * y").find("position 5"), std::string::npos) << message("x * * y");
  EXPECT_NE(message("").find("empty"), std::string::npos);
  EXPECT_NE(message("x^2.5").find("unexpected '.'"), std::string::npos) << message("x^2.5");
}

TEST(BBTetra, ChangeOfBasisReproducesThePolynomial) {
  std::mt19937 rng(5);
  for (int degree = 1; degree <= 6; ++degree) {
    const Polynomial3 f = randomPolynomial(rng, degree);
    const Tetrahedron v = randomTet(rng);
    const BBTetra b = BBTetra::fromPolynomial(f, v);
    ASSERT_EQ(b.degree(), degree);
    for (int a = 0; a < 4; ++a) {
      MultiIndex4 m = {0, 0, 0, 0};
      m[std::size_t(a)] = degree;
      EXPECT_NEAR(b.coefficient(m), f.eval(v[std::size_t(a)]), 1e-11);  // vertex coefficient = f(Va)
    }
    for (int s = 0; s < 20; ++s) {
      const Vector4d l = randomBary(rng);
      const Vector3d p = l[0] * v[0] + l[1] * v[1] + l[2] * v[2] + l[3] * v[3];
      EXPECT_NEAR(b.evalBarycentric(l), f.eval(p), 1e-11);
      EXPECT_NEAR(b.elevated().evalBarycentric(l), f.eval(p), 1e-11);
    }
  }
}

TEST(BBTetra, DegreeTwoMatchesBBQuadric) {
  std::mt19937 rng(9);
  const Polynomial3 f = randomPolynomial(rng, 2);
  const Tetrahedron v = randomTet(rng);
  const BBTetra b = BBTetra::fromPolynomial(f, v);
  const Quadric q = b.toBBQuadric().toQuadric();
  for (int s = 0; s < 10; ++s) {
    const Vector3d p = Vector3d::Random();
    EXPECT_NEAR(q.eval(p), f.eval(p), 1e-11);
  }
}

TEST(BBTetra, ReducingAnElevatedSimplexReturnsIt) {
  std::mt19937 rng(11);
  std::uniform_real_distribution<double> u(-1.0, 1.0);
  for (int target = 1; target <= 4; ++target) {
    BBTetra b(target, randomTet(rng));
    for (const auto& m : BBTetra::multiIndices(target)) b.setCoefficient(m, u(rng));
    BBTetra e = b;
    for (int k = 0; k < 4; ++k) e = e.elevated();
    EXPECT_LT(maxAbsDiff(e.reducedTo(target), b), 1e-12) << "target degree " << target;
  }
  // A quadric given as a polynomial and elevated to degree 5.
  const Polynomial3 sphere = Polynomial3::parse("x^2 + y^2 + z^2 - 1");
  const Tetrahedron v = randomTet(rng);
  const BBTetra q = BBTetra::fromPolynomial(sphere, v);
  EXPECT_LT(maxAbsDiff(q.elevated().elevated().elevated().reducedTo(2), q), 1e-12);
}

TEST(BBTetra, ClosedFormulas55EqualTheGeneralAlgorithm) {
  std::mt19937 rng(13);
  std::uniform_real_distribution<double> u(-2.0, 2.0);
  for (int trial = 0; trial < 50; ++trial) {
    BBTetra b(4, randomTet(rng));
    for (const auto& m : BBTetra::multiIndices(4)) b.setCoefficient(m, u(rng));
    const BBTetra general = b.reducedTo(2);
    const BBTetra closed = reduceQuarticClosedForm(b);
    EXPECT_LT(maxAbsDiff(general, closed), 1e-12);
  }
  // One hand-checked value: edge 0-1 of the quartic with B4000 = 1, B3100 = 2, B1300 = 3,
  // B0400 = 4: A1100 = -1/2 + 2 - 2 + 3 = 2.5.
  BBTetra b(4, randomTet(rng));
  b.setCoefficient({4, 0, 0, 0}, 1);
  b.setCoefficient({3, 1, 0, 0}, 2);
  b.setCoefficient({1, 3, 0, 0}, 3);
  b.setCoefficient({0, 4, 0, 0}, 4);
  EXPECT_NEAR(b.reducedTo(2).coefficient({1, 1, 0, 0}), 2.5, 1e-14);
}

TEST(BBTetra, GeneralAlgorithmEqualsTheVertexEdgeRule) {
  std::mt19937 rng(17);
  for (int degree = 3; degree <= 8; ++degree) {
    const Polynomial3 f = randomPolynomial(rng, degree);
    const Tetrahedron v = randomTet(rng);
    const BBTetra general = BBTetra::fromPolynomial(f, v).reducedTo(2);
    const BBTetra rule = reduceByVertexRule(f, v);
    double scale = 0;
    for (double c : rule.coefficients()) scale = std::max(scale, std::fabs(c));
    EXPECT_LT(maxAbsDiff(general, rule), 1e-10 * std::max(1.0, scale)) << "degree " << degree;
  }
}

TEST(BBTetra, StrictSignMeansNoZero) {
  const Polynomial3 f = Polynomial3::parse("x^4 + y^4 + z^4 - 1");
  const Tetrahedron inside = {Vector3d(0, 0, 0), Vector3d(0.3, 0, 0), Vector3d(0, 0.3, 0), Vector3d(0, 0, 0.3)};
  const Tetrahedron outside = {Vector3d(2, 2, 2), Vector3d(2.5, 2, 2), Vector3d(2, 2.5, 2), Vector3d(2, 2, 2.5)};
  const Tetrahedron across = {Vector3d(0, 0, 0), Vector3d(1.5, 0, 0), Vector3d(0, 1.5, 0), Vector3d(0, 0, 1.5)};
  EXPECT_EQ(BBTetra::fromPolynomial(f, inside).strictSign(), -1);
  EXPECT_EQ(BBTetra::fromPolynomial(f, outside).strictSign(), 1);
  EXPECT_EQ(BBTetra::fromPolynomial(f, across).strictSign(), 0);
}

TEST(KuhnMesh, SplitIsConformingAndFillsTheBox) {
  const Eigen::AlignedBox3d box(Vector3d(-1, -2, 0.5), Vector3d(2, 1, 1.5));
  const TetMesh m = kuhnMesh(box, 3, 2, 4);
  ASSERT_EQ(m.tets.size(), std::size_t(6 * 3 * 2 * 4));
  double vol = 0;
  for (std::size_t t = 0; t < m.tets.size(); ++t) {
    EXPECT_GT(std::fabs(m.volume(t)), 0.0);
    vol += std::fabs(m.volume(t));
  }
  EXPECT_NEAR(vol, box.volume(), 1e-12);
  // Every face is shared by exactly two tetrahedra, except faces on the box boundary.
  std::map<std::array<int, 3>, int> faces;
  for (const auto& t : m.tets)
    for (int a = 0; a < 4; ++a) {
      std::array<int, 3> f;
      int k = 0;
      for (int b = 0; b < 4; ++b)
        if (b != a) f[std::size_t(k++)] = t[std::size_t(b)];
      std::sort(f.begin(), f.end());
      ++faces[f];
    }
  for (const auto& kv : faces) {
    bool onBoundary = false;
    for (int axis = 0; axis < 3; ++axis)
      for (double c : {box.min()[axis], box.max()[axis]}) {
        bool all = true;
        for (int v : kv.first) all = all && m.vertices[std::size_t(v)][axis] == c;
        onBoundary = onBoundary || all;
      }
    EXPECT_EQ(kv.second, onBoundary ? 1 : 2);
  }
  // Random points lie in exactly one tetrahedron.
  std::mt19937 rng(2);
  std::uniform_real_distribution<double> u(0.0, 1.0);
  for (int s = 0; s < 200; ++s) {
    const Vector3d p = box.min() + box.sizes().cwiseProduct(Vector3d(u(rng), u(rng), u(rng)));
    int inside = 0;
    for (std::size_t t = 0; t < m.tets.size(); ++t) {
      Tetrahedron v;
      for (int a = 0; a < 4; ++a) v[std::size_t(a)] = m.vertices[std::size_t(m.tets[t][std::size_t(a)])];
      BBTetra b(0, v);
      const Vector4d l = b.barycentric(p);
      if (l.minCoeff() > 0) ++inside;
    }
    EXPECT_EQ(inside, 1);
  }
}

TEST(KuhnMesh, BeyRefinementIsTheKuhnMeshOfHalfTheSpacing) {
  const Eigen::AlignedBox3d box(Vector3d(0, 0, 0), Vector3d(2, 2, 2));
  auto key = [](std::array<Vector3d, 4> t) {
    std::array<std::array<double, 3>, 4> k;
    for (int a = 0; a < 4; ++a) k[std::size_t(a)] = {t[std::size_t(a)].x(), t[std::size_t(a)].y(), t[std::size_t(a)].z()};
    std::sort(k.begin(), k.end());
    return k;
  };
  const TetMesh coarse = kuhnMesh(box, 2, 2, 2), fine = kuhnMesh(box, 4, 4, 4);
  std::set<std::array<std::array<double, 3>, 4>> a, b;
  for (const auto& t : coarse.tets) {
    std::array<Vector3d, 4> v;
    for (int i = 0; i < 4; ++i) v[std::size_t(i)] = coarse.vertices[std::size_t(t[std::size_t(i)])];
    for (const auto& c : refineBey(v)) a.insert(key(c));
  }
  for (const auto& t : fine.tets) {
    std::array<Vector3d, 4> v;
    for (int i = 0; i < 4; ++i) v[std::size_t(i)] = fine.vertices[std::size_t(t[std::size_t(i)])];
    b.insert(key(v));
  }
  EXPECT_EQ(a.size(), fine.tets.size());
  EXPECT_TRUE(a == b);
}

TEST(DegreeReduction, PiecesJoinG0AcrossEveryInternalFace) {
  const Polynomial3 f = Polynomial3::parse(kTorus, {{"R", 1.0}, {"r", 0.4}});
  const Eigen::AlignedBox3d box(Vector3d(-1.5, -1.5, -0.5), Vector3d(1.5, 1.5, 0.5));
  for (bool smooth : {false, true}) {
    DegreeReductionOptions o;
    o.level = 3;
    o.cull = false;  // one primitive per tetrahedron, in mesh order
    o.smooth = smooth;
    const DegreeReductionResult r = reduceAlgebraic(f, box, o);
    const TetMesh m = kuhnMesh(box, 3, 3, 3);
    ASSERT_EQ(r.primitives.size(), m.tets.size());
    std::map<std::array<int, 3>, std::vector<std::size_t>> faces;
    for (std::size_t t = 0; t < m.tets.size(); ++t)
      for (int a = 0; a < 4; ++a) {
        std::array<int, 3> fc;
        int k = 0;
        for (int b = 0; b < 4; ++b)
          if (b != a) fc[std::size_t(k++)] = m.tets[t][std::size_t(b)];
        std::sort(fc.begin(), fc.end());
        faces[fc].push_back(t);
      }
    int internal = 0;
    double worst = 0;
    for (const auto& kv : faces) {
      if (kv.second.size() != 2) continue;
      ++internal;
      const Quadric& q1 = r.primitives[kv.second[0]].quadric;
      const Quadric& q2 = r.primitives[kv.second[1]].quadric;
      const Vector3d a = m.vertices[std::size_t(kv.first[0])], b = m.vertices[std::size_t(kv.first[1])],
                     c = m.vertices[std::size_t(kv.first[2])];
      for (int i = 0; i <= 6; ++i)
        for (int j = 0; i + j <= 6; ++j) {
          const Vector3d p = a + (b - a) * (i / 6.0) + (c - a) * (j / 6.0);
          worst = std::max(worst, std::fabs(q1.eval(p) - q2.eval(p)));
        }
    }
    EXPECT_EQ(internal, 270);  // 27 cubes x 6 inside + 54 cube faces x 2
    EXPECT_LT(worst, 1e-11) << "smooth " << smooth;
  }
}

TEST(DegreeReduction, CullingDropsOnlyCellsEmptyForBothSurfaces) {
  const Polynomial3 f = Polynomial3::parse("x^4 + y^4 + z^4 - 1");
  const Eigen::AlignedBox3d box(Vector3d(-1.2, -1.2, -1.2), Vector3d(1.2, 1.2, 1.2));
  DegreeReductionOptions all, culled;
  all.level = culled.level = 4;
  all.cull = false;
  const auto ra = reduceAlgebraic(f, box, all);
  const auto rc = reduceAlgebraic(f, box, culled);
  EXPECT_LT(rc.primitives.size(), ra.primitives.size());
  EXPECT_EQ(rc.kept_cells, int(rc.primitives.size()));
  // Every dropped cell: neither f nor the reduced piece vanishes at sampled points inside.
  const TetMesh m = kuhnMesh(box, 4, 4, 4);
  std::set<std::vector<double>> keptQ;
  for (const auto& p : rc.primitives) keptQ.insert(std::vector<double>(p.quadric.Q.data(), p.quadric.Q.data() + 16));
  std::mt19937 rng(4);
  int dropped = 0;
  for (std::size_t t = 0; t < m.tets.size(); ++t) {
    const auto& q = ra.primitives[t].quadric;
    if (keptQ.count(std::vector<double>(q.Q.data(), q.Q.data() + 16))) continue;
    ++dropped;
    Tetrahedron v;
    for (int a = 0; a < 4; ++a) v[std::size_t(a)] = m.vertices[std::size_t(m.tets[t][std::size_t(a)])];
    const double s = f.eval(v[0]) > 0 ? 1 : -1;
    for (int k = 0; k < 30; ++k) {
      const Vector4d l = randomBary(rng);
      const Vector3d p = l[0] * v[0] + l[1] * v[1] + l[2] * v[2] + l[3] * v[3];
      EXPECT_GT(s * f.eval(p), 0.0);
      EXPECT_GT(s * q.eval(p), 0.0);
    }
  }
  EXPECT_EQ(dropped, int(ra.primitives.size() - rc.primitives.size()));
}

TEST(DegreeReduction, ErrorShrinksWithLevelAndRefinementMeetsTheBound) {
  const Polynomial3 f = Polynomial3::parse(kTorus, {{"R", 1.0}, {"r", 0.4}});
  const Eigen::AlignedBox3d box(Vector3d(-1.5, -1.5, -0.5), Vector3d(1.5, 1.5, 0.5));
  double prev = 1e9;
  for (int level : {2, 4, 8}) {
    DegreeReductionOptions o;
    o.level = level;
    const auto r = reduceAlgebraic(f, box, o);
    EXPECT_GT(r.error.samples, 0);
    EXPECT_LT(r.error.max(), prev) << "level " << level;
    prev = r.error.max();
  }
  EXPECT_LT(prev, 0.02);
  DegreeReductionOptions o;
  o.level = 2;
  o.refine_error = 0.01;
  const auto r = reduceAlgebraic(f, box, o);
  EXPECT_LE(r.error.max(), 0.01);
  EXPECT_GT(r.level, 2);
}

TEST(DegreeReduction, PiecesOnOneQuadricMerge) {
  // A quadric given as an algebraic surface: every cell reduces to it exactly.
  const Polynomial3 f = Polynomial3::parse("x^2 + 2 y^2 + z^2 - 1");
  const Eigen::AlignedBox3d box(Vector3d(-1.1, -1.1, -1.1), Vector3d(1.1, 1.1, 1.1));
  DegreeReductionOptions o;
  o.level = 4;
  const auto plain = reduceAlgebraic(f, box, o);
  EXPECT_EQ(plain.distinct_quadrics, 1);
  EXPECT_GT(plain.primitives.size(), 100u);
  o.merge = true;
  const auto merged = reduceAlgebraic(f, box, o);
  ASSERT_EQ(merged.primitives.size(), 1u);
  EXPECT_EQ(merged.primitives[0].clip.size(), 6u);
  for (const Vector3d& p : {Vector3d(1, 0, 0), Vector3d(0, std::sqrt(0.5), 0), Vector3d(0.6, 0, 0.8)})
    EXPECT_NEAR(merged.primitives[0].quadric.eval(p), 0.0, 1e-12);
  // The torus's pieces are all different quadrics.
  const Polynomial3 t = Polynomial3::parse(kTorus, {{"R", 1.0}, {"r", 0.4}});
  DegreeReductionOptions ot;
  ot.level = 4;
  const auto rt = reduceAlgebraic(t, Eigen::AlignedBox3d(Vector3d(-1.5, -1.5, -0.5), Vector3d(1.5, 1.5, 0.5)), ot);
  EXPECT_GT(rt.distinct_quadrics, 10);
  EXPECT_LE(rt.distinct_quadrics, rt.kept_cells);
}
