// Trivariate simplex B-splines (DMS, digest §3) over a tetrahedralisation: w = F(x, y, z),
// displayed as the surface F = 0. The same construction as SimplexSpline2 one dimension up:
// knot clouds t_i,0..n (t_i,0 = vertex i), knot sets V^I_β of n + 4 knots, the recursion
// M(u | V) = Σ_j λ_j(u) M(u | V \ v_j) down to 1_[v0..v3)(u) / |d| (d = 6 x volume, half-open),
// N^I_β = |d(t_i0,β0, .., t_i3,β3)| M(u | V^I_β).
//
// Cells: convex polyhedra (each a list of half-spaces) obtained by splitting the mesh
// tetrahedra (∩ an optional domain box) by the plane of every knot triangle (three knots of
// one knot set) that crosses the cell's interior; F is one polynomial in each. A cell is
// emitted only if that polynomial's degree-2 BB coefficients on the cell's parent
// tetrahedron are not all of one strict sign (convex hull: otherwise F has no zero in the
// parent, hence none in the cell — culling never opens a hole).
#pragma once
#include <array>
#include <vector>

#include <Eigen/Dense>

#include "modeling/polynomial3.h"
#include "modeling/primitive.h"

namespace qacc {

class SimplexSpline3 {
 public:
  using Vec = Eigen::Vector3d;
  using Beta = std::array<int, 4>;

  SimplexSpline3(int degree, std::vector<Vec> vertices, std::vector<std::array<int, 4>> tets,
                 std::vector<std::vector<Vec>> knots);

  int degree() const { return n_; }
  const std::vector<std::array<int, 4>>& tets() const { return tets_; }
  static std::vector<Beta> multiIndices(int n);
  Vec knot(int vertex, int k) const { return k == 0 ? verts_[std::size_t(vertex)] : knots_[std::size_t(vertex)][std::size_t(k) - 1]; }
  std::vector<Vec> knotSet(std::size_t tet, const Beta& b) const;
  std::vector<Vec> lowerSet(std::size_t tet, const Beta& b) const;

  double basis(std::size_t tet, const Beta& b, const Vec& u) const;
  void setCoefficients(std::vector<std::vector<double>> c) { coef_ = std::move(c); }
  double eval(const Vec& u) const;
  Polynomial3 localPolynomial(const Vec& probe) const;
  // Coefficients sampling a field at the Greville points (mean of U^I_β).
  std::vector<std::vector<double>> grevilleCoefficients(const Polynomial3& h) const;

  void setDomain(const Eigen::AlignedBox3d& d) { domain_ = d; }

  struct Cell {
    std::vector<HalfSpace> faces;  // facets of the convex cell
    std::vector<Vec> corners;      // its vertices
    Polynomial3 poly;              // F inside
    std::size_t parent = 0;        // mesh tetrahedron it lies in
    bool crossed = true;           // F may vanish in it (BB sign test on the parent)
  };
  std::vector<Cell> cells() const;
  // The surface F = 0: one quadric per crossed cell, clipped by the cell's facets.
  std::vector<Primitive> toPrimitives(int material = 0, int object = 0) const;

 private:
  int n_;
  std::vector<Vec> verts_;
  std::vector<std::array<int, 4>> tets_;
  std::vector<std::vector<Vec>> knots_;
  std::vector<std::vector<double>> coef_;
  Eigen::AlignedBox3d domain_;
};

// Knot clouds: "G0" on the vertices, "G1" generic offsets of relative size `radius`.
std::vector<std::vector<Eigen::Vector3d>> knotClouds3(const std::vector<Eigen::Vector3d>& vertices,
                                                     const std::vector<std::array<int, 4>>& tets, int degree,
                                                     bool g1, double radius = 0.15);

}  // namespace qacc
