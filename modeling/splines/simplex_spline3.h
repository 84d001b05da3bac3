// Trivariate simplex B-splines (DMS, digest §3) over a tetrahedralisation: w = F(x, y, z),
// displayed as the surface F = 0. Knot clouds, knot sets, the recursion and coefficients are
// SimplexSplineBase<3> (simplex_spline_base.h); with generic knot clouds F is C1 (G1
// surfaces for degree 2), with knots on the vertices it is Bernstein-Bézier per tetrahedron
// joined C0 (G0).
//
// Cells: F = Σ over the leaves of the compiled recursion of 1_S(u) c w Π λ(u), so F is one
// polynomial in each cell of the arrangement of the leaves' knot simplices S. Each mesh
// tetrahedron (∩ the optional domain box) is cut recursively (convex_polyhedron.h) by the
// planes of the faces of the simplices that straddle it, from the basis functions whose
// support box overlaps it; coinciding planes (within 1e-11 relative) are one plane, cut once,
// so neighbouring cells get exactly opposite half-spaces. A region is cut by the plane,
// among the first 16 (largest triangle first) that one of whose triangles crosses its
// interior, that leaves most of it on its thinner side; planes that cross no triangle inside
// a region are dropped for its whole subtree, and a region that straddles no simplex any
// more is a cell. Its polynomial (a quadric for degree <= 2) is the sum of the simplices
// that contain it, carried down the recursion.
//
// Culling (crossedCells, toPrimitives) never drops a cell F can vanish in:
//  - a tetrahedron is dropped when the coefficients of every basis function whose support
//    box overlaps it have one strict sign (F = Σ c_k N_k with N_k >= 0, not all zero);
//  - a region is dropped before being cut further when a bound on F there excludes 0: the
//    simplices containing it summed exactly, each straddled one counted between 0 and its
//    term, terms bounded over the region's corners and over the simplex (BB hull);
//  - a cell is dropped when its quadric's values at the corners have one strict sign and
//    its BB coefficients have that sign on the parent tetrahedron, or on every tetrahedron
//    of a fan covering the cell (convex hull property).
// View culling (`view`, loader/view_culling.h): a tetrahedron or a region whose polyhedron
// misses the view volume is dropped before it is cut further; every other region is cut
// exactly as without a view (a region's cuts depend only on itself), so the cells that
// remain are the unculled model's.
// Tetrahedra are processed in parallel (OpenMP); the output order is the tetrahedra's.
//
// Bounded work (toPrimitives' maxRegions, the scene's --max-cells): the regions a
// decomposition makes (each tetrahedron meeting the domain, and two per cut) are not known
// before it runs. A sample of up to kRegionSample tetrahedra, evenly spread over the list, is
// decomposed first and their regions extrapolated to all tetrahedra; an estimate above twice
// the limit is refused before the others are cut (RegionLimitExceeded, estimated). The
// regions are also counted while the tetrahedra are cut, sample included, and the moment the
// count passes the limit the decomposition stops (RegionLimitExceeded, counted), so the limit
// is exact whatever the estimate said. The sample's cells are kept, not made twice.
#pragma once
#include <array>
#include <cstdint>
#include <stdexcept>
#include <vector>

#include <Eigen/Dense>

#include "modeling/geometry/primitive.h"
#include "modeling/scene/view_volume.h"
#include "modeling/splines/simplex_spline_base.h"

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
    std::size_t regions_culled = 0;  // regions (those tetrahedra included) dropped before being cut into cells
    std::size_t cells = 0;           // cells made
    std::size_t crossed = 0;         // cells F can vanish in (emitted)
    std::size_t planes = 0;          // distinct cutting planes of the tetrahedra (summed)
    std::size_t view_culled = 0;     // tetrahedra and regions dropped because they miss the view
    std::size_t regions = 0;         // regions made: the tetrahedra above and two per cut
    CellStats& operator+=(const CellStats& o);
  };
  // Tetrahedra decomposed first to estimate the regions of all (see the file comment).
  static constexpr std::size_t kRegionSample = 64;
  // The decomposition asked for more regions than maxRegions.
  struct RegionLimitExceeded : std::runtime_error {
    RegionLimitExceeded(std::size_t regions, std::size_t sampled, std::size_t tets);
    std::size_t regions;  // the estimate, or maxRegions + 1 when counted
    std::size_t sampled;  // tetrahedra of the sample the estimate came from; 0 when counted
    std::size_t tets;     // tetrahedra of the mesh
  };
  // Every cell: convex polyhedra covering the tetrahedralisation (∩ domain), one quadric
  // each, `crossed` set by the cell tests. Degree <= 2.
  std::vector<Cell> cells(CellStats* stats = nullptr) const;
  // Only the cells F can vanish in: tetrahedra and regions culled before they are cut.
  std::vector<Cell> crossedCells(CellStats* stats = nullptr) const;
  // The surface F = 0: one quadric per crossed cell (every cell with cull = false), clipped by
  // the cell's facets.
  // At most maxRegions regions are made (RegionLimitExceeded beyond, see the file comment).
  std::vector<Primitive> toPrimitives(int material = 0, int object = 0, CellStats* stats = nullptr,
                                      bool cull = true, const ViewVolume* view = nullptr,
                                      std::size_t maxRegions = SIZE_MAX) const;

 private:
  struct RegionCount;
  std::vector<Cell> decompose(bool cull, CellStats* stats, const ViewVolume* view = nullptr,
                              std::size_t maxRegions = SIZE_MAX) const;
  std::vector<Cell> decomposeTet(std::size_t tet, bool cull, double eps, CellStats& stats,
                                 const ViewVolume* view, RegionCount& regions) const;
};

// Knot clouds for a tetrahedralisation (simplexKnotClouds<3>).
inline std::vector<std::vector<Eigen::Vector3d>> knotClouds3(const std::vector<Eigen::Vector3d>& vertices,
                                                            const std::vector<std::array<int, 4>>& tets, int degree,
                                                            bool g1, double radius = 0.15) {
  return simplexKnotClouds<3>(vertices, tets, degree, g1, radius);
}

}  // namespace qacc
