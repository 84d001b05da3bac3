// Marching tetrahedra on the Kuhn mesh (facets of algebraic surfaces at equal error):
// vertices on the surface, a closed mesh, errors measured both ways that shrink with level.
#include <gtest/gtest.h>

#include <cmath>
#include <map>

#include "modeling/algebraic/marching_tetrahedra.h"

using namespace qacc;
using Eigen::Vector3d;

TEST(MarchingTetrahedra, SphereMeshIsClosedAndConverges) {
  const Polynomial3 f = Polynomial3::parse("x^2 + y^2 + z^2 - 1");
  const Eigen::AlignedBox3d box(Vector3d(-1.3, -1.3, -1.3), Vector3d(1.3, 1.3, 1.3));
  double prev = 1e9;
  for (int level : {4, 8, 16}) {
    const TriangleSoup m = marchingTetrahedra(f, box, level);
    ASSERT_FALSE(m.triangles.empty());
    for (const auto& v : m.vertices) EXPECT_NEAR(v.norm(), 1.0, 1e-12);
    std::map<std::pair<int, int>, int> edges;
    for (const auto& t : m.triangles)
      for (int e = 0; e < 3; ++e) {
        int a = t[std::size_t(e)], b = t[std::size_t(e + 1) % 3];
        // Oriented outward: the normal points along ∇f = 2p.
        ++edges[{std::min(a, b), std::max(a, b)}];
      }
    for (const auto& kv : edges) EXPECT_EQ(kv.second, 2);
    for (const auto& t : m.triangles) {
      const Vector3d a = m.vertices[std::size_t(t[0])], b = m.vertices[std::size_t(t[1])], c = m.vertices[std::size_t(t[2])];
      EXPECT_GT((b - a).cross(c - a).dot(a + b + c), 0.0);
    }
    const FacetError e = facetError(f, m, box);
    EXPECT_GT(e.samples, 100);
    EXPECT_LT(e.max, prev);
    // The largest chord gap of a triangle of edge h on a unit sphere is about h^2 / 8.
    EXPECT_LT(e.max, std::pow(2.6 * std::sqrt(3.0) / level, 2));
    prev = e.max;
  }
  // A mesh that misses the surface has infinite error: an empty mesh.
  EXPECT_FALSE(std::isfinite(facetError(f, TriangleSoup{}, box).max));
}

TEST(MarchingTetrahedra, MeshOfSizeHitsTheTriangleBudget) {
  const Polynomial3 f = Polynomial3::parse("x^4 + y^4 + z^4 - 1");
  const Eigen::AlignedBox3d box(Vector3d(-1.2, -1.2, -1.2), Vector3d(1.2, 1.2, 1.2));
  int previous = 0;
  for (std::size_t budget : {300u, 3000u, 20000u, 80000u}) {
    int level = 0;
    const TriangleSoup m = marchingTetrahedraOfSize(f, box, budget, &level);
    EXPECT_GT(level, previous);
    // The same mesh as the plain call at that level.
    EXPECT_EQ(m.triangles.size(), marchingTetrahedra(f, box, level).triangles.size());
    EXPECT_GT(double(m.triangles.size()), 0.75 * double(budget)) << budget;
    EXPECT_LT(double(m.triangles.size()), 1.33 * double(budget)) << budget;
    previous = level;
  }
}
