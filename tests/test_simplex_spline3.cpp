// Trivariate simplex B-splines (3-simplex volumes, issue 6): partition of unity, cells that
// reproduce the spline, G0 across cell faces, culling that keeps every cell F can vanish in.
#include <gtest/gtest.h>

#include <cmath>
#include <random>

#include "modeling/kuhn_mesh.h"
#include "modeling/simplex_spline3.h"

using namespace qacc;
using Eigen::Vector3d;

namespace {

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
        worst = std::max(worst, std::fabs(c.poly.eval(p) - s.eval(p)));
        // A cell culled as empty has F of one strict sign at its points.
        if (!c.crossed) {
          EXPECT_GT(c.poly.eval(p) * c.poly.eval(c.corners[0]), 0.0);
        }
      }
      crossed += c.crossed;
    }
    EXPECT_LT(worst, 1e-9) << "g1 " << g1;
    EXPECT_GT(crossed, 0);
    // G0: on each cell's facets, the polynomial of the cell just across agrees.
    double gap = 0;
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
        const Vector3d out = m + 1e-6 * h.p.head<3>().normalized();
        for (std::size_t j = 0; j < cells.size(); ++j) {
          if (j == i) continue;
          bool inside = true;
          for (const auto& g : cells[j].faces) inside = inside && g.eval(out) < 0;
          if (!inside) continue;
          gap = std::max(gap, std::fabs(cells[i].poly.eval(m) - cells[j].poly.eval(m)));
          break;
        }
      }
    EXPECT_LT(gap, 1e-9) << "g1 " << g1;
  }
}
