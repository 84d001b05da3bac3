// Marching tetrahedra (design §3.3, §5), the one walk of the Kuhn mesh (kuhn_mesh.h) that
// every field uses: the algebraic surfaces here and the quadric pieces of the tessellation
// (modeling/tessellation/marching_piece.h).
//
// marchKuhnGrid is the walk itself: a grid of field samples, a point inside where its value
// is <= 0 (NaN is outside), each tetrahedron whose corners are on both sides handed to the
// caller as one triangle (one corner alone on its side) or one quadrilateral (two and two)
// of crossed edges; where a crossed edge's point goes, and how the triangles are oriented
// and stored, is the caller's.
//
// marchingTetrahedra below is a triangle mesh of the algebraic surface f = 0 inside a box,
// on the same conforming Kuhn mesh as the degree reduction, so that quadric pieces and
// facets can be compared on equal terms (count vs geometric error). Vertices lie on the
// surface (bisection of f along each sign-changing edge, shared by the tetrahedra around the
// edge, so the mesh is watertight inside the box); triangles are oriented with their normal
// along ∇f.
#pragma once
#include <array>
#include <cstdint>
#include <functional>
#include <vector>

#include <Eigen/Dense>

#include "modeling/algebraic/polynomial3.h"

namespace qacc {

// An edge of the Kuhn mesh crossed by the surface, its lower-indexed end first.
struct KuhnEdge {
  Eigen::Vector3i a, b;        // grid coordinates of the ends
  std::int64_t ia = 0, ib = 0; // their indices in the samples, ia < ib
};

// What marchKuhnGrid hands over per crossing tetrahedron. A triangle (e0, e1, e2) has the
// lone corner's three edges in tetrahedron order; a quadrilateral (e0, e1, e2, e3) is
// (in0-out0, in0-out1, in1-out1, in1-out0), to be split as (e0, e1, e2) and (e0, e2, e3).
struct KuhnCrossings {
  std::function<void(const KuhnEdge&, const KuhnEdge&, const KuhnEdge&)> triangle;
  std::function<void(const KuhnEdge&, const KuhnEdge&, const KuhnEdge&, const KuhnEdge&)> quad;
};

// Walks the Kuhn mesh of cubes.x() x cubes.y() x cubes.z() cubes (each >= 1), cube by cube
// in grid order and the 6 tetrahedra of a cube in kuhnCubeTets order. `samples` holds the
// field at the grid points, point (i, j, k) at (k (ny + 1) + j) (nx + 1) + i.
void marchKuhnGrid(const Eigen::Vector3i& cubes, const std::vector<double>& samples, const KuhnCrossings& out);

struct TriangleSoup {
  std::vector<Eigen::Vector3d> vertices;
  std::vector<std::array<int, 3>> triangles;
};

// `level` cubes per axis (>= 1). The mesh is walked cube by cube: memory is the grid's
// values and the output, so fine levels (256: 17 M grid points) stay affordable.
TriangleSoup marchingTetrahedra(const Polynomial3& f, const Eigen::AlignedBox3d& box, int level);

// The finest grid marchingTetrahedraOfSize uses (cubes per axis).
constexpr int kMaxMarchingLevel = 256;
// A mesh of about `triangles` triangles (a tessellation level given as a triangle budget):
// the count grows as the square of the grid, so the grid is predicted from a 16-cube pilot
// mesh, clamped to kMaxMarchingLevel and corrected once more when the count is more than
// 20 % off; budgets below the pilot's count try every coarser grid (which may not resolve
// the surface and stray from the square law), and 64 is tried when the pilot misses the
// surface. The closest count wins; the level used is returned in *level when given.
TriangleSoup marchingTetrahedraOfSize(const Polynomial3& f, const Eigen::AlignedBox3d& box, std::size_t triangles,
                                      int* level = nullptr);

// Sampled two-sided distance between the triangles and f = 0 inside the box:
//  - triangles → surface: Newton projection along ∇f of each triangle's centroid and edge
//    midpoints;
//  - surface → triangles: exact distance from points of f = 0 (roots along axis-parallel
//    lines of a 40 x 40 grid per axis, Bernstein isolation) to the nearest triangle among
//    those within one bucket (box / 16 per axis) around it; a point with no triangle that
//    close (a sheet the mesh misses) counts as infinitely far.
struct FacetError {
  double max = 0, mean = 0;
  int samples = 0;
};
FacetError facetError(const Polynomial3& f, const TriangleSoup& mesh, const Eigen::AlignedBox3d& box);

}  // namespace qacc
