// AlgebraicSurface: the true surface f(x, y, z) = 0 of a polynomial of any degree inside an
// axis-aligned box, ray-cast exactly for the reference renderer (ExactSurface). Along a
// segment the polynomial is restricted to the part of the segment inside the box, expanded
// in t, converted to the Bernstein basis and its first root isolated by Bernstein
// subdivision (modeling/bernstein_roots.h: robust, no fixed-step marching; the tolerances
// are stated there). The normal is ∇f at the hit. Its triangles are a marching-tetrahedra
// mesh of the box (marching_tetrahedra.h) with unit ∇f normals, measured by facetError.
#pragma once
#include <vector>

#include <Eigen/Dense>

#include "modeling/geometry/exact_surface.h"
#include "modeling/geometry/half_space.h"
#include "modeling/algebraic/polynomial3.h"

namespace qacc {

class AlgebraicSurface : public ExactSurface {
 public:
  AlgebraicSurface(Polynomial3 f, const Eigen::AlignedBox3d& box);

  bool intersect(const Eigen::Vector3d& p0, const Eigen::Vector3d& p1, ExactHit& hit) const override;
  Eigen::AlignedBox3d bounds() const override { return box_; }
  ExactSurfaceMesh tessellate(std::size_t triangles) const override;

  // Every root of the segment (parameters in [0, 1], increasing) inside the box.
  std::vector<double> allRoots(const Eigen::Vector3d& p0, const Eigen::Vector3d& p1) const;

  const Polynomial3& polynomial() const { return f_; }

 private:
  Polynomial3 f_;
  Eigen::AlignedBox3d box_;
  // Parameters [t0, t1] of the segment inside the closed box; false if it misses.
  bool clipToBox(const Eigen::Vector3d& p0, const Eigen::Vector3d& d, double& t0, double& t1) const;
};

// Restriction of a convex clip region (intersection of half-spaces) to a segment
// p0 + t d, t in [t0, t1]: narrows [t0, t1]; false when it becomes empty.
bool clipSegmentToHalfSpaces(const std::vector<HalfSpace>& clip, const Eigen::Vector3d& p0,
                             const Eigen::Vector3d& d, double& t0, double& t1);

}  // namespace qacc
