// PlacedExactSurface: an exact surface modelled in an object's local frame, placed in the
// world by the object's affine transform (X_world = M X_local) and restricted to the
// object's clip half-spaces (local frame, as the loader applies "clip" before
// "transform"). The convex clip region cuts a segment to one interval, so the first hit
// inside it is the inner surface's first hit on the sub-segment. Its triangles are the
// inner surface's, cut by the clip planes in the local frame (a cut point lies on the
// triangle's edge, its normal interpolated along it) and then placed: positions by M,
// normals by M's inverse transpose, winding kept consistent with the normals when M
// mirrors. The error is the inner mesh's, unclipped, times M's largest stretch.
#pragma once
#include <memory>
#include <vector>

#include <Eigen/Dense>

#include "modeling/geometry/exact_surface.h"
#include "modeling/geometry/half_space.h"

namespace qacc {

class PlacedExactSurface : public ExactSurface {
 public:
  // Throws std::invalid_argument unless M is affine (last row 0 0 0 1) and invertible.
  PlacedExactSurface(std::shared_ptr<const ExactSurface> inner, const Eigen::Matrix4d& M,
                     std::vector<HalfSpace> local_clip = {});

  bool intersect(const Eigen::Vector3d& p0, const Eigen::Vector3d& p1, ExactHit& hit) const override;
  Eigen::AlignedBox3d bounds() const override;
  ExactSurfaceMesh tessellate(std::size_t triangles) const override;

 private:
  std::shared_ptr<const ExactSurface> inner_;
  Eigen::Matrix4d M_, Minv_;
  std::vector<HalfSpace> clip_;
};

}  // namespace qacc
