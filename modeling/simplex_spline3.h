// Trivariate simplex B-splines (DMS, digest §3) over a tetrahedralisation: w = F(x, y, z),
// displayed as the surface F = 0. Knot clouds, knot sets, the recursion and coefficients are
// SimplexSplineBase<3> (simplex_spline_base.h); with generic knot clouds F is C1 (G1
// surfaces for degree 2), with knots on the vertices it is Bernstein-Bézier per tetrahedron
// joined C0 (G0).
//
// Cells: F is one polynomial in each cell of the arrangement of the knot triangles (three
// knots of one knot set). Each mesh tetrahedron (∩ the optional domain box) is cut
// recursively (convex_polyhedron.h): a region is split by the first plane, in order of
// decreasing triangle area, one of whose knot triangles crosses its interior; the planes
// that cross no triangle inside a region are dropped for its whole subtree. Knot triangles
// are taken only from the basis functions whose support box meets the tetrahedron; planes
// that coincide (within 1e-11 relative) are one plane, cut once, so neighbouring cells get
// exactly opposite half-spaces. Each cell's polynomial is the recursion run symbolically at
// its centroid.
//
// Culling (crossedCells, toPrimitives) never drops a cell F can vanish in:
//  - a region is dropped before being split further when the coefficients of every basis
//    function whose support box meets it have one strict sign (F is a convex combination
//    of them there: partition of unity, N >= 0);
//  - a cell is dropped when its polynomial's degree-2 BB coefficients have one strict sign
//    on the parent tetrahedron, or on every tetrahedron of a fan covering the cell
//    (convex hull property), unless its corners already show both signs.
// Tetrahedra are processed in parallel (OpenMP); the output order is the tetrahedra's.
#pragma once
#include <array>
#include <vector>

#include <Eigen/Dense>

#include "modeling/primitive.h"
#include "modeling/simplex_spline_base.h"

namespace qacc {

class SimplexSpline3 : public SimplexSplineBase<3> {
 public:
  using Vec = Eigen::Vector3d;

  // knots[i] = t_i,1..t_i,n (n points; t_i,0 = vertices[i] is implicit).
  SimplexSpline3(int degree, std::vector<Vec> vertices, std::vector<std::array<int, 4>> tets,
                 std::vector<std::vector<Vec>> knots)
      : SimplexSplineBase<3>("SimplexSpline3", degree, 3, std::move(vertices), std::move(tets), std::move(knots)) {}

  const std::vector<std::array<int, 4>>& tets() const { return simplices(); }

  struct Cell {
    std::vector<HalfSpace> faces;  // facets of the convex cell
    std::vector<Vec> corners;      // its vertices
    Quadric quadric;               // F inside (degree <= 2)
    std::size_t parent = 0;        // mesh tetrahedron it lies in
    bool crossed = true;           // F may vanish in it (see the culling rules above)
  };
  struct CellStats {
    std::size_t tets = 0;            // mesh tetrahedra meeting the domain
    std::size_t tets_culled = 0;     // dropped whole by the coefficient signs
    std::size_t regions_culled = 0;  // regions (tetrahedra included) dropped before their cells were made
    std::size_t cells = 0;           // cells made (polynomial computed)
    std::size_t crossed = 0;         // cells F can vanish in (emitted)
    std::size_t planes = 0;          // distinct knot-triangle planes met by the tetrahedra (summed)
    CellStats& operator+=(const CellStats& o);
  };
  // Every cell: convex polyhedra covering the tetrahedralisation (∩ domain), one polynomial
  // each, `crossed` set by the BB tests.
  std::vector<Cell> cells(CellStats* stats = nullptr) const;
  // Only the cells F can vanish in, regions of one coefficient sign dropped before splitting.
  std::vector<Cell> crossedCells(CellStats* stats = nullptr) const;
  // The surface F = 0: one quadric per crossed cell, clipped by the cell's facets.
  std::vector<Primitive> toPrimitives(int material = 0, int object = 0, CellStats* stats = nullptr) const;

 private:
  std::vector<Cell> decompose(bool cull, CellStats* stats) const;
  std::vector<Cell> decomposeTet(std::size_t tet, bool cull, bool unity, double eps, CellStats& stats) const;
  // Per tetrahedron: is it (∩ domain) farther than the knot reach from the complex's
  // boundary, where the basis is a partition of unity?
  std::vector<bool> partitionOfUnity() const;
};

// Knot clouds for a tetrahedralisation (simplexKnotClouds<3>).
inline std::vector<std::vector<Eigen::Vector3d>> knotClouds3(const std::vector<Eigen::Vector3d>& vertices,
                                                            const std::vector<std::array<int, 4>>& tets, int degree,
                                                            bool g1, double radius = 0.15) {
  return simplexKnotClouds<3>(vertices, tets, degree, g1, radius);
}

}  // namespace qacc
