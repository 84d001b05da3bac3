// Trivariate simplex B-splines (3-simplex volumes, issue 6): partition of unity, exact
// quadratics, cells that reproduce the spline, G0 across cell faces (and G1 with generic
// knots), culling that keeps every cell F can vanish in (every zero of F found along random
// segments lies in an emitted cell), deterministic output for any thread count; the
// "bspline" scene type with "dimension": 3 (its cells, its errors) and renders of the shipped
// volume scenes without pinholes.
#include <gtest/gtest.h>

#include <omp.h>

#include <algorithm>
#include <cmath>
#include <filesystem>
#include <map>
#include <memory>
#include <random>
#include <string>

#include "modeling/splines/bspline_object.h"
#include "modeling/algebraic/kuhn_mesh.h"
#include "modeling/scene/scene_error.h"
#include "modeling/loader/scene_loader.h"
#include "modeling/splines/simplex_spline3.h"
#include "raster/reference/reference_renderer.h"
#include "tests/sanitized_build.h"
#include "tests/tools/render_checks.h"
#include "tools/engines/engine.h"

using namespace qacc;
using Eigen::Vector3d;

namespace {

// Largest value and gradient gaps across the cells' faces: for each face, its corners'
// centroid m and the cell just across (found at m + 1e-7 n, through a grid of cell boxes).
struct FaceGaps {
  double value = 0, gradient = 0;  // gradient: relative to the larger of the two gradients
  int faces = 0;
};
FaceGaps faceGaps(const std::vector<SimplexSpline3::Cell>& cells) {
  Eigen::AlignedBox3d all;
  for (const auto& c : cells)
    for (const auto& v : c.corners) all.extend(v);
  const double size = all.sizes().maxCoeff() / 24;
  auto key = [&](const Vector3d& p) {
    const Eigen::Array3i k = ((p - all.min()) / size).array().floor().cast<int>();
    return std::array<int, 3>{k[0], k[1], k[2]};
  };
  std::map<std::array<int, 3>, std::vector<std::size_t>> grid;
  for (std::size_t i = 0; i < cells.size(); ++i) {
    Eigen::AlignedBox3d b;
    for (const auto& v : cells[i].corners) b.extend(v);
    const auto lo = key(b.min()), hi = key(b.max());
    for (int x = lo[0]; x <= hi[0]; ++x)
      for (int y = lo[1]; y <= hi[1]; ++y)
        for (int z = lo[2]; z <= hi[2]; ++z) grid[{x, y, z}].push_back(i);
  }
  FaceGaps g;
  for (std::size_t i = 0; i < cells.size(); ++i)
    for (const auto& h : cells[i].faces) {
      Vector3d m = Vector3d::Zero();
      int on = 0;
      for (const auto& v : cells[i].corners)
        if (std::fabs(h.eval(v)) <= 1e-9 * h.p.head<3>().norm()) {
          m += v;
          ++on;
        }
      m /= on;
      const Vector3d out = m + 1e-7 * h.p.head<3>().normalized();
      const auto it = grid.find(key(out));
      if (it == grid.end()) continue;
      for (std::size_t j : it->second) {
        if (j == i) continue;
        bool inside = true;
        for (const auto& f : cells[j].faces) inside = inside && f.eval(out) < 0;
        if (!inside) continue;
        ++g.faces;
        const Vector3d a = cells[i].quadric.gradient(m), b = cells[j].quadric.gradient(m);
        g.value = std::max(g.value, std::fabs(cells[i].quadric.eval(m) - cells[j].quadric.eval(m)));
        g.gradient = std::max(g.gradient, (a - b).norm() / std::max(a.norm(), b.norm()));
        break;
      }
    }
  return g;
}

SimplexSpline3 makeSpline(bool g1) {
  const TetMesh m = kuhnMesh(Eigen::AlignedBox3d(Vector3d(-1.5, -1.5, -1.5), Vector3d(1.5, 1.5, 1.5)), 3, 3, 3);
  SimplexSpline3 s(2, m.vertices, m.tets, knotClouds3(m.vertices, m.tets, 2, g1, 0.15));
  s.setDomain(Eigen::AlignedBox3d(Vector3d(-0.5, -0.5, -0.5), Vector3d(0.5, 0.5, 0.5)));
  return s;
}

}  // namespace

TEST(SimplexSpline3, BasisIsAPartitionOfUnityInsideTheDomain) {
  std::mt19937 rng(1);
  std::uniform_real_distribution<double> u(-0.5, 0.5);
  for (bool g1 : {false, true}) {
    SimplexSpline3 s = makeSpline(g1);
    std::vector<std::vector<double>> ones(s.tets().size(), std::vector<double>(10, 1.0));
    s.setCoefficients(ones);
    for (int k = 0; k < 30; ++k) {
      const Vector3d p(u(rng), u(rng), u(rng));
      EXPECT_NEAR(s.eval(p), 1.0, 1e-10) << "g1 " << g1 << " at " << p.transpose();
    }
  }
}

TEST(SimplexSpline3, CellsReproduceTheSplineAndJoinG0) {
  std::mt19937 rng(2);
  std::uniform_real_distribution<double> w(0.0, 1.0);
  const Polynomial3 field = Polynomial3::parse("x^2 + y^2 + z^2 - 0.16 + 0.3 x y z");
  for (bool g1 : {false, true}) {
    // Two tetrahedra of one Kuhn cube sharing a face, no domain: the cells need no partition
    // of unity (kept small: the 3D cell decomposition is the expensive part).
    const TetMesh mesh = kuhnMesh(Eigen::AlignedBox3d(Vector3d(-0.5, -0.5, -0.5), Vector3d(0.5, 0.5, 0.5)), 1, 1, 1);
    const std::vector<std::array<int, 4>> two = {mesh.tets[0], mesh.tets[1]};
    SimplexSpline3 s(2, mesh.vertices, two, knotClouds3(mesh.vertices, two, 2, g1, 0.15));
    s.setCoefficients(s.grevilleCoefficients(field));
    const auto cells = s.cells();
    EXPECT_GT(cells.size(), g1 ? 20u : 1u);
    if (!g1) {
      EXPECT_EQ(cells.size(), 2u);  // knots on the vertices: one cell per tetrahedron
    }
    double worst = 0;
    int crossed = 0;
    for (const auto& c : cells) {
      // Random convex combinations of the corners are inside the cell.
      for (int k = 0; k < 4; ++k) {
        Vector3d p = Vector3d::Zero();
        double sum = 0;
        for (const auto& v : c.corners) {
          const double a = w(rng);
          p += a * v;
          sum += a;
        }
        p /= sum;
        worst = std::max(worst, std::fabs(c.quadric.eval(p) - s.eval(p)));
        // A cell culled as empty has F of one strict sign at its points.
        if (!c.crossed) {
          EXPECT_GT(c.quadric.eval(p) * c.quadric.eval(c.corners[0]), 0.0);
        }
      }
      crossed += c.crossed;
    }
    EXPECT_LT(worst, 1e-9) << "g1 " << g1;
    EXPECT_GT(crossed, 0);
    // G0 on each cell's facets; generic knots also join with equal gradients (C1), knots on
    // the vertices do not (a crease along the shared tetrahedron face).
    const FaceGaps gaps = faceGaps(cells);
    EXPECT_GE(gaps.faces, int(cells.size()));
    EXPECT_LT(gaps.value, 1e-9) << "g1 " << g1;
    if (g1)
      EXPECT_LT(gaps.gradient, 1e-7);
    else
      EXPECT_GT(gaps.gradient, 1e-2);
  }
}

TEST(SimplexSpline3, ReproducesQuadraticsExactly) {
  std::mt19937 rng(3);
  std::uniform_real_distribution<double> u(-0.5, 0.5);
  const Polynomial3 q = Polynomial3::parse("0.7 x^2 - 1.3 x y + 0.4 y^2 + 0.5 y z - 0.8 z^2 + 0.2 x - 0.9 z + 0.1");
  for (bool g1 : {false, true}) {
    SimplexSpline3 s = makeSpline(g1);
    s.setCoefficients(s.blossomCoefficients(q));
    for (int k = 0; k < 40; ++k) {
      const Vector3d p(u(rng), u(rng), u(rng));
      EXPECT_NEAR(s.eval(p), q.eval(p), 1e-10);
    }
  }
  // Every cell's quadric is q itself (one Kuhn cube, generic knots, inside the knot reach).
  const TetMesh mesh = kuhnMesh(Eigen::AlignedBox3d(Vector3d(-0.5, -0.5, -0.5), Vector3d(0.5, 0.5, 0.5)), 1, 1, 1);
  SimplexSpline3 s(2, mesh.vertices, mesh.tets, knotClouds3(mesh.vertices, mesh.tets, 2, true, 0.15));
  s.setCoefficients(s.blossomCoefficients(q));
  const double d = 0.5 - s.knotReach();  // where Σ N = 1
  s.setDomain(Eigen::AlignedBox3d(Vector3d(-d, -d, -d), Vector3d(d, d, d)));
  const auto cells = s.cells();
  ASSERT_GT(cells.size(), 10u);
  for (const auto& c : cells)
    for (int k = 0; k < 5; ++k) {
      const Vector3d p(u(rng), u(rng), u(rng));
      EXPECT_NEAR(c.quadric.eval(p), q.eval(p), 1e-9);
    }
}

// A closed surface in an n x n x n Kuhn grid of [-h, h]³ shown inside the knot reach.
SimplexSpline3 blob(bool g1, int n = 2, double h = 1, double radius = 0.2,
                    const char* field = "x^2 + y^2 + z^2 + 0.5 x y z - 0.36") {
  const TetMesh m = kuhnMesh(Eigen::AlignedBox3d(Vector3d(-h, -h, -h), Vector3d(h, h, h)), n, n, n);
  SimplexSpline3 s(2, m.vertices, m.tets, knotClouds3(m.vertices, m.tets, 2, g1, radius));
  const double d = h - s.knotReach();
  s.setDomain(Eigen::AlignedBox3d(Vector3d(-d, -d, -d), Vector3d(d, d, d)));
  s.setCoefficients(s.grevilleCoefficients(Polynomial3::parse(field)));
  return s;
}

// Zeros of F along random segments from near the centre to anywhere in the domain (sign
// changes on 200 steps, then bisection) must lie in one of `cells`, whose quadric vanishes
// there. `withoutOne` counts the zeros missed when the cell of the first zero is left out,
// so that the check is seen to fail.
struct ZeroCheck {
  int roots = 0, missing = 0, withoutOne = 0;
  double worst = 0;
};
ZeroCheck zerosInCells(const SimplexSpline3& s, const std::vector<SimplexSpline3::Cell>& cells, std::mt19937& rng,
                       int segments) {
  ZeroCheck z;
  const double d = s.domain().max().x();
  std::uniform_real_distribution<double> u(-d, d), c(-0.2, 0.2);
  std::size_t dropped = cells.size();
  for (int k = 0; k < segments; ++k) {
    const Vector3d a(c(rng), c(rng), c(rng)), b(u(rng), u(rng), u(rng));
    double fp = s.eval(a);
    for (int i = 1; i <= 200; ++i) {
      const Vector3d p = a + (b - a) * (double(i - 1) / 200), q = a + (b - a) * (double(i) / 200);
      const double fq = s.eval(q);
      if ((fp < 0) != (fq < 0)) {
        Vector3d lo = p, hi = q;
        for (int it = 0; it < 60; ++it) {
          const Vector3d m = 0.5 * (lo + hi);
          ((s.eval(m) < 0) == (fp < 0) ? lo : hi) = m;
        }
        const Vector3d x = 0.5 * (lo + hi);
        ++z.roots;
        bool found = false, foundWithout = false;
        for (std::size_t ci = 0; ci < cells.size(); ++ci) {
          bool in = true;
          for (const auto& h : cells[ci].faces) in = in && h.eval(x) <= 1e-9 * h.p.head<3>().norm();
          if (!in) continue;
          if (dropped == cells.size()) dropped = ci;
          found = true;
          foundWithout = foundWithout || ci != dropped;
          z.worst = std::max(z.worst, std::fabs(cells[ci].quadric.eval(x)));
        }
        z.missing += !found;
        z.withoutOne += !foundWithout;
      }
      fp = fq;
    }
  }
  return z;
}

TEST(SimplexSpline3, CullingKeepsEveryZeroOfTheSpline) {
  std::mt19937 rng(4);
  for (bool g1 : {false, true}) {
    const SimplexSpline3 s = blob(g1);
    SimplexSpline3::CellStats all, kept;
    const auto full = s.cells(&all);
    const auto cells = s.crossedCells(&kept);
    EXPECT_EQ(all.cells, full.size());
    EXPECT_EQ(kept.crossed, cells.size());
    EXPECT_LT(cells.size(), full.size());
    if (g1) {
      EXPECT_LT(cells.size(), full.size() / 4);
      EXPECT_GT(kept.regions_culled, 0u);
    }
    // The emitted cells are cells of the full decomposition that it marks crossed too (the
    // region culling only skips work).
    std::map<std::vector<double>, const SimplexSpline3::Cell*> byCorners;
    auto key = [](const SimplexSpline3::Cell& c) {
      std::vector<double> k;
      for (const auto& v : c.corners) k.insert(k.end(), v.data(), v.data() + 3);
      return k;
    };
    for (const auto& c : full) byCorners[key(c)] = &c;
    for (const auto& c : cells) {
      const auto it = byCorners.find(key(c));
      ASSERT_NE(it, byCorners.end());
      EXPECT_TRUE(it->second->crossed);
      EXPECT_EQ((it->second->quadric.Q - c.quadric.Q).cwiseAbs().maxCoeff(), 0.0);
    }
    const ZeroCheck z = zerosInCells(s, cells, rng, 60);
    EXPECT_GT(z.roots, 40) << "g1 " << g1;
    EXPECT_EQ(z.missing, 0) << "g1 " << g1;
    EXPECT_GT(z.withoutOne, 0) << "g1 " << g1;
    EXPECT_LT(z.worst, 1e-9) << "g1 " << g1;
  }
}

TEST(SimplexSpline3, CullingDoesNotAssumeAPartitionOfUnity) {
  // Knot clouds of 0.6 x the shortest edge: the basis sums to more than 1 in small places
  // (0.3 % of the domain, up to 1.004) even beyond the knot reach, so a bound that assumed
  // Σ N = 1 there dropped regions F vanishes in (5 of the zeros below were missed); the bounds
  // used hold for any knots.
  std::mt19937 rng(5);
  const SimplexSpline3 s = blob(true, 3, 1.5, 0.6, "x^2 + y^2 + z^2 - 0.5");
  SimplexSpline3 ones = s;
  ones.setCoefficients(std::vector<std::vector<double>>(s.tets().size(), std::vector<double>(10, 1.0)));
  const double d = s.domain().max().x();
  std::uniform_real_distribution<double> u(-d, d);
  double excess = 0;
  for (int k = 0; k < 20000; ++k) excess = std::max(excess, ones.eval(Vector3d(u(rng), u(rng), u(rng))) - 1);
  EXPECT_GT(excess, 1e-3);
  const ZeroCheck z = zerosInCells(s, s.crossedCells(), rng, 100);
  EXPECT_GT(z.roots, 60);
  EXPECT_EQ(z.missing, 0);
  EXPECT_LT(z.worst, 1e-9);
}

TEST(SimplexSpline3, SameCellsForAnyThreadCount) {
  const SimplexSpline3 s = blob(true);
  const int before = omp_get_max_threads();
  omp_set_num_threads(1);
  const auto one = s.crossedCells();
  omp_set_num_threads(3);
  const auto three = s.crossedCells();
  omp_set_num_threads(before);
  ASSERT_EQ(one.size(), three.size());
  for (std::size_t i = 0; i < one.size(); ++i) {
    EXPECT_EQ(one[i].quadric.Q, three[i].quadric.Q);
    ASSERT_EQ(one[i].faces.size(), three[i].faces.size());
    for (std::size_t f = 0; f < one[i].faces.size(); ++f) EXPECT_EQ(one[i].faces[f].p, three[i].faces[f].p);
  }
}

// The "bspline" scene type with "dimension": 3.
namespace {

std::string volumeScene(const std::string& keys, int size = 160) {
  return R"js({"format": "qacc-scene/1", "image": {"width": )js" + std::to_string(size) + R"js(, "height": )js" +
         std::to_string(size) + R"js(},
    "camera": {"type": "perspective", "eye": [2.2, -2.9, 1.9], "target": [0, 0, 0], "up": [0, 0, 1], "fov_y_deg": 30},
    "objects": [{"type": "bspline", "dimension": 3, "grid": {"min": [-1, -1, -1], "max": [1, 1, 1], "n": 2},
                 "field": "x^2 + y^2 + z^2 + 0.5 x y z - 0.36")js" +
         keys + "}]}";
}

SimplexSpline3 volumeOf(const std::string& text) {
  const nlohmann::json doc = nlohmann::json::parse(text);
  return readBsplineVolume(JsonNode(doc["objects"][0], "/objects/0", std::make_shared<const std::string>("v.json")));
}

}  // namespace

TEST(SimplexSpline3, SceneTypeEmitsTheCrossedCells) {
  std::mt19937 rng(6);
  std::uniform_real_distribution<double> w(0.0, 1.0);
  for (const char* continuity : {"G0", "G1"}) {
    const std::string text = volumeScene(std::string(R"js(, "continuity": ")js") + continuity + "\"");
    const Scene scene = parseScene(text, "v.json", ".");
    ASSERT_EQ(scene.objects.size(), 1u);
    EXPECT_NE(scene.objects[0].note.find("emitted"), std::string::npos);
    // The object's primitives are the spline's crossed cells, and those reproduce it.
    const SimplexSpline3 s = volumeOf(text);
    const auto cells = s.crossedCells();
    ASSERT_EQ(scene.primitives.size(), cells.size()) << continuity;
    double worst = 0;
    for (std::size_t i = 0; i < cells.size(); ++i) {
      const Primitive& p = scene.primitives[i];
      EXPECT_EQ(p.quadric.Q, cells[i].quadric.Q);
      ASSERT_EQ(p.clip.size(), cells[i].faces.size());
      for (std::size_t f = 0; f < p.clip.size(); ++f) EXPECT_EQ(p.clip[f].p, cells[i].faces[f].p);
      for (int k = 0; k < 3; ++k) {
        Vector3d x = Vector3d::Zero();
        double sum = 0;
        for (const auto& v : cells[i].corners) {
          const double a = w(rng);
          x += a * v;
          sum += a;
        }
        x /= sum;
        worst = std::max(worst, std::fabs(p.quadric.eval(x) - s.eval(x)));
      }
    }
    EXPECT_LT(worst, 1e-9) << continuity;
    if (std::string(continuity) == "G0") {
      for (const auto& p : scene.primitives) EXPECT_EQ(p.clip.size(), 4u);  // one cell per tetrahedron
    }
    // Values agree across every face between emitted cells; gradients too for G1 knots,
    // not for G0 knots (creases along the tetrahedron faces).
    const FaceGaps gaps = faceGaps(cells);
    EXPECT_GT(gaps.faces, int(cells.size()));
    EXPECT_LT(gaps.value, 1e-9) << continuity;
    if (std::string(continuity) == "G1")
      EXPECT_LT(gaps.gradient, 1e-7);
    else
      EXPECT_GT(gaps.gradient, 1e-2);
  }
  // Taylor sampling reproduces a quadratic field: every cell is the sphere itself.
  const Scene sphere = parseScene(
      R"js({"format": "qacc-scene/1", "camera": {"eye": [0, 0, 5]},
        "objects": [{"type": "bspline", "dimension": 3, "grid": {"min": [-1, -1, -1], "max": [1, 1, 1], "n": [2, 2, 2]},
                     "field": "x^2 + y^2 + z^2 - 0.36", "sampling": "taylor", "knot_radius": 0.3}]})js",
      "t.json", ".");
  ASSERT_GT(sphere.primitives.size(), 20u);
  for (const auto& p : sphere.primitives) {
    const Eigen::Matrix4d d = p.quadric.Q - Eigen::Vector4d(1, 1, 1, -0.36).asDiagonal().toDenseMatrix();
    EXPECT_LT(d.cwiseAbs().maxCoeff(), 1e-9);
  }
}

TEST(SimplexSpline3, SceneTypeErrorsNameFileAndPath) {
  auto fails = [](const std::string& keys, const std::string& where) {
    try {
      parseScene(volumeScene(keys), "bad.json", ".");
      ADD_FAILURE() << "accepted " << keys;
    } catch (const SceneError& e) {
      EXPECT_EQ(e.file(), "bad.json");
      EXPECT_EQ(e.jsonPath(), where) << e.what();
    }
  };
  fails(R"js(, "degree": 3)js", "/objects/0/degree");
  fails(R"js(, "continuity": "C1")js", "/objects/0/continuity");
  fails(R"js(, "sampling": "nearest")js", "/objects/0/sampling");
  fails(R"js(, "height": "x")js", "/objects/0/height");
  fails(R"js(, "triangles": [[0, 1, 2]])js", "/objects/0/triangles");
  fails(R"js(, "domain": [[-1, -1], [1, 1]])js", "/objects/0/domain/0");
  fails(R"js(, "domain": [[1, -1, -1], [-1, 1, 1]])js", "/objects/0/domain");
  fails(R"js(, "knots": [])js", "/objects/0/knots");
  fails(R"js(, "params": [1])js", "/objects/0/params");
  fails(R"js(, "volume": true)js", "/objects/0/volume");
  auto failsWhole = [](const std::string& text, const std::string& where) {
    try {
      parseScene(text, "bad.json", ".");
      ADD_FAILURE() << "accepted " << text;
    } catch (const SceneError& e) {
      EXPECT_EQ(e.jsonPath(), where) << e.what();
    }
  };
  const std::string head = R"js({"format": "qacc-scene/1", "camera": {"eye": [0, 0, 5]}, "objects": [{"type": "bspline", )js";
  failsWhole(head + R"js("dimension": 4, "grid": {"min": [0, 0], "max": [1, 1], "n": 1}, "height": "x"}]})js",
             "/objects/0/dimension");
  failsWhole(head + R"js("dimension": 3, "grid": {"min": [0, 0], "max": [1, 1, 1], "n": 1}, "field": "x"}]})js",
             "/objects/0/grid/min");
  failsWhole(head + R"js("dimension": 3, "grid": {"min": [0, 0, 0], "max": [1, 1, 1], "n": [2, 2]}, "field": "x"}]})js",
             "/objects/0/grid/n");
  failsWhole(head + R"js("dimension": 3, "grid": {"min": [0, 0, 0], "max": [1, 1, 1], "n": 1}, "field": "x +"}]})js",
             "/objects/0/field");
  failsWhole(head + R"js("grid": {"min": [0, 0], "max": [1, 1], "n": 1}, "field": "x"}]})js", "/objects/0/field");
  failsWhole(head + R"js("dimension": 3, "vertices": [[0, 0, 0], [1, 0, 0], [0, 1, 0], [0, 0, 1]],
                         "tetrahedra": [[0, 1, 2]], "field": "x"}]})js",
             "/objects/0/tetrahedra/0");
  failsWhole(head + R"js("dimension": 3, "vertices": [[0, 0, 0], [1, 0, 0], [0, 1, 0], [0, 0, 1]],
                         "tetrahedra": [[0, 1, 2, 3]], "coefficients": [[1, 2, 3]]}]})js",
             "/objects/0/coefficients/0");
}

TEST(SimplexSpline3, SceneCullingChangesNoPixel) {
  // "cull": false emits every cell of the decomposition; the culled scene draws the same.
  const Scene culled = parseScene(volumeScene(""), "v.json", ".");
  const Scene full = parseScene(volumeScene(R"js(, "cull": false)js"), "v.json", ".");
  EXPECT_LT(4 * culled.primitives.size(), full.primitives.size());
  const FrameBuffer a = renderReference(culled, 2), b = renderReference(full, 2);
  EXPECT_GT(a.covered(), 2000u);
  int differ = 0;
  for (std::size_t i = 0; i < a.depth.size(); ++i)
    differ += (a.object[i] >= 0) != (b.object[i] >= 0) || (a.object[i] >= 0 && a.depth[i] != b.depth[i]);
  EXPECT_EQ(differ, 0);
}

TEST(SimplexSpline3, ShippedVolumeScenesRenderWithoutPinholes) {
  // The torus of scenes/bspline_volume_{g0,g1}.json, at 200 x 150: the accelerator's image has
  // no pinhole, covers what the exact render of the same cells covers, and neither shows the
  // inside of the closed surface; the check fails when a cell is removed.
  for (const char* name : {"/scenes/bspline_volume_g0.json", "/scenes/bspline_volume_g1.json"}) {
    // The G1 volume's build of 107 k cells (145 s under ASan) is left to the Release run under
    // the sanitizers; SceneTypeEmitsTheCrossedCells builds G1 volumes there (tests/sanitized_build.h).
    if (leftOutOfSanitizedSweeps(std::filesystem::path(name).stem().string())) continue;
    Scene s = loadScene(std::string(QACC_SOURCE_DIR) + name);
    s.width = 200;
    s.height = 150;
    const FrameBuffer ref = renderReference(s, 2);
    EngineOptions eo;
    eo.threads = 2;
    eo.report_accuracy = false;
    const FrameBuffer hw = runEngine("hw", s, eo).fb;
    EXPECT_GT(ref.covered(), 5000u) << name;
    EXPECT_EQ(pinholes(ref), 0) << name;
    EXPECT_EQ(pinholes(hw), 0) << name;
    EXPECT_EQ(insideViews(s, ref), 0) << name;
    EXPECT_EQ(insideViews(s, hw), 0) << name << " hw";
    EXPECT_EQ(missedInside(ref, hw, 1), 0) << name;
    // Remove the cells seen along the middle row on the torus's near side: the inside shows.
    Scene holed = s;
    std::vector<int> victims;
    for (int x = 0; x < s.width; ++x) {
      const int p = ref.primitive[std::size_t(110 * s.width + x)];
      if (p >= 0) victims.push_back(p);
    }
    std::sort(victims.begin(), victims.end());
    victims.erase(std::unique(victims.begin(), victims.end()), victims.end());
    for (auto it = victims.rbegin(); it != victims.rend(); ++it) holed.primitives.erase(holed.primitives.begin() + *it);
    EXPECT_GT(insideViews(holed, renderReference(holed, 2)), 20) << name;
  }
}
