// Tetrahedral meshes of a box (digest §4): the box is cut into nx x ny x nz cubes
// (cells of a grid) and every cube into 6 tetrahedra by the Kuhn split — the 6 monotone
// edge paths from the cube's minimum corner to its maximum corner, one tetrahedron each.
// The same diagonal is used in every cube, so the mesh is conforming: two tetrahedra
// share either nothing, a vertex, a whole edge or a whole face.
//
// refineBey splits a tetrahedron 1 → 8 (4 corner tetrahedra + the central octahedron cut
// into 4 along the diagonal x02–x13, Bey's rule). Applied to the Kuhn tetrahedra of a grid
// (vertices in path order) it yields exactly the Kuhn tetrahedra of the grid of half the
// spacing, so uniform refinement keeps the mesh conforming.
#pragma once
#include <array>
#include <vector>

#include <Eigen/Dense>

namespace qacc {

struct TetMesh {
  std::vector<Eigen::Vector3d> vertices;
  std::vector<std::array<int, 4>> tets;  // vertex indices, in Kuhn path order for Kuhn meshes
  std::vector<int> cube;                 // for Kuhn meshes: index of the cube of each tetrahedron
  int nx = 0, ny = 0, nz = 0;            // grid size (Kuhn meshes)

  double volume(std::size_t t) const;  // signed volume of tetrahedron t
  // Index of the grid vertex (i, j, k), 0 <= i <= nx, ...
  int gridVertex(int i, int j, int k) const { return (k * (ny + 1) + j) * (nx + 1) + i; }
};

// Kuhn mesh of `box` with n cubes per axis (nx, ny, nz >= 1). Grid coordinates are
// computed as min + (max - min) * i / n, so shared vertices are bit-identical.
TetMesh kuhnMesh(const Eigen::AlignedBox3d& box, int nx, int ny, int nz);

// Grid vertex (i, j, k) of the Kuhn mesh of `box` with n = (nx, ny, nz) cubes per axis,
// bit-identical to kuhnMesh's vertex (for meshes walked cube by cube without storing them).
Eigen::Vector3d kuhnGridPoint(const Eigen::AlignedBox3d& box, const Eigen::Vector3i& n, int i, int j, int k);
// The 6 tetrahedra of the cube whose minimum grid corner is (i, j, k): grid coordinates of
// their vertices in Kuhn path order, in kuhnMesh's order.
using KuhnCubeTets = std::array<std::array<Eigen::Vector3i, 4>, 6>;
KuhnCubeTets kuhnCubeTets(int i, int j, int k);

// Bey's 1 → 8 split of the tetrahedron (x0, x1, x2, x3); midpoints are (xi + xj) / 2.
std::array<std::array<Eigen::Vector3d, 4>, 8> refineBey(const std::array<Eigen::Vector3d, 4>& t);

}  // namespace qacc
