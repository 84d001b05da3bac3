// Triangle meshes: OBJ parsing (polygons, negative indices, v/vt/vn corners, errors with
// file and line) and facet primitives.
#include <gtest/gtest.h>

#include <stdexcept>
#include <string>

#include "modeling/modelers/triangle_mesh.h"

using namespace qacc;

namespace {

// True when x lies on the facet: on its plane (within tol) and inside all edge half-spaces.
bool onFacet(const Primitive& p, const Eigen::Vector3d& x, double tol = 1e-12) {
  if (std::abs(p.quadric.eval(x)) > tol) return false;
  for (const auto& h : p.clip)
    if (!h.contains(x)) return false;
  return true;
}

std::string errorOf(const std::string& text) {
  try {
    parseObj(text, "mesh.obj");
  } catch (const std::runtime_error& e) {
    return e.what();
  }
  return "";
}

}  // namespace

TEST(TriangleMesh, QuadsAreFanTriangulated) {
  const TriangleMesh m = parseObj("# a unit square and a pentagon\n"
                                  "v 0 0 0\nv 1 0 0\nv 1 1 0\nv 0 1 0\n"
                                  "f 1 2 3 4\n"
                                  "v 0 0 1\nv 1 0 1\nv 2 1 1\nv 1 2 1\nv 0 1 1\n"
                                  "f 5 6 7 8 9\n",
                                  "t.obj");
  ASSERT_EQ(m.vertices.size(), 9u);
  ASSERT_EQ(m.triangles.size(), 2u + 3u);
  EXPECT_EQ(m.triangles[0], (std::array<int, 3>{0, 1, 2}));
  EXPECT_EQ(m.triangles[1], (std::array<int, 3>{0, 2, 3}));
  EXPECT_EQ(m.triangles[4], (std::array<int, 3>{4, 7, 8}));
}

TEST(TriangleMesh, NegativeIndicesAndCornerForms) {
  const TriangleMesh m = parseObj("v 0 0 0\nv 1 0 0\nv 0 1 0\n"
                                  "vt 0 0\nvt 1 0\nvt 0 1\nvn 0 0 1\n"
                                  "f -3 -2 -1\n"
                                  "f 1/1 2/2 3/3\n"
                                  "f 1//1 2//1 3//1\n"
                                  "f 1/1/1 2/2/1 3/3/1\n"
                                  "v 5 5 5 2\n"  // homogeneous weight
                                  "f -4 -3 -1\n"
                                  "o name\ng group\ns off\nusemtl x\n",
                                  "t.obj");
  ASSERT_EQ(m.triangles.size(), 5u);
  for (int t = 0; t < 4; ++t) EXPECT_EQ(m.triangles[std::size_t(t)], (std::array<int, 3>{0, 1, 2}));
  // Negative indices are relative to the vertices read so far.
  EXPECT_EQ(m.triangles[4], (std::array<int, 3>{0, 1, 3}));
  EXPECT_TRUE(m.vertices[3].isApprox(Eigen::Vector3d(2.5, 2.5, 2.5)));
}

TEST(TriangleMesh, ErrorsNameFileAndLine) {
  EXPECT_EQ(errorOf("v 0 0 0\nv 1 0 0\nv 0 1 0\nf 1 2 4\n").rfind("mesh.obj:4: vertex index 4 out of range", 0), 0u)
      << errorOf("v 0 0 0\nv 1 0 0\nv 0 1 0\nf 1 2 4\n");
  EXPECT_EQ(errorOf("v 0 0\n").rfind("mesh.obj:1: a vertex needs 3 coordinates", 0), 0u);
  EXPECT_EQ(errorOf("v 0 0 x\n").rfind("mesh.obj:1: bad vertex coordinate 'x'", 0), 0u);
  EXPECT_EQ(errorOf("v 0 0 1e999\n").rfind("mesh.obj:1: bad vertex coordinate", 0), 0u);
  EXPECT_EQ(errorOf("v 0 0 0\n\nf 1 1\n").rfind("mesh.obj:3: a face needs at least 3 corners", 0), 0u);
  EXPECT_EQ(errorOf("v 0 0 0\nf 0 1 1\n").rfind("mesh.obj:2: bad vertex index '0'", 0), 0u);
  EXPECT_EQ(errorOf("v 0 0 0\nf -2 1 1\n").rfind("mesh.obj:2: vertex index -2 out of range", 0), 0u);
  EXPECT_EQ(errorOf("v 0 0 0\nv 1 0 0\nv 0 1 0\nf 1 2 3\n"), "");
  try {
    readObj("/nonexistent/dir/mesh.obj");
    FAIL() << "missing file accepted";
  } catch (const std::runtime_error& e) {
    EXPECT_NE(std::string(e.what()).find("/nonexistent/dir/mesh.obj: cannot open"), std::string::npos) << e.what();
  }
}

TEST(TriangleMesh, FacetPrimitivesCoverTheirTriangles) {
  TriangleMesh m;
  m.vertices = {{0, 0, 0}, {2, 0, 0}, {0, 2, 0}, {0, 0, 3}, {4, 0, 0}};
  m.triangles = {{0, 1, 2}, {0, 1, 3}, {0, 1, 4} /* degenerate: collinear */};
  std::size_t skipped = 0;
  const auto prims = meshPrimitives(m, &skipped);
  ASSERT_EQ(prims.size(), 2u);
  EXPECT_EQ(skipped, 1u);
  for (const auto& p : prims) {
    EXPECT_TRUE(p.isPlanar());
    EXPECT_EQ(p.clip.size(), 3u);
  }
  EXPECT_TRUE(onFacet(prims[0], {0.5, 0.5, 0}));
  EXPECT_FALSE(onFacet(prims[0], {1.5, 1.5, 0}));   // beyond the hypotenuse
  EXPECT_FALSE(onFacet(prims[0], {0.5, 0.5, 0.1}));  // off the plane
  EXPECT_TRUE(onFacet(prims[1], {0.5, 0, 1}));
  EXPECT_FALSE(onFacet(prims[1], {-0.5, 0, 1}));
}
