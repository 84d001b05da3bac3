// PlacedExactSurface: an exact surface modelled in an object's local frame, placed in the
// world by the object's affine transform (X_world = M X_local) and restricted to the
// object's clip half-spaces (local frame, as the loader applies "clip" before
// "transform"). The convex clip region cuts a segment to one interval, so the first hit
// inside it is the inner surface's first hit on the sub-segment.
#pragma once
#include <memory>
#include <vector>

#include <Eigen/Dense>

#include "modeling/exact_surface.h"
#include "modeling/half_space.h"

namespace qacc {

class PlacedExactSurface : public ExactSurface {
 public:
  // Throws std::invalid_argument unless M is affine (last row 0 0 0 1) and invertible.
  PlacedExactSurface(std::shared_ptr<const ExactSurface> inner, const Eigen::Matrix4d& M,
                     std::vector<HalfSpace> local_clip = {});

  bool intersect(const Eigen::Vector3d& p0, const Eigen::Vector3d& p1, ExactHit& hit) const override;
  Eigen::AlignedBox3d bounds() const override;

 private:
  std::shared_ptr<const ExactSurface> inner_;
  Eigen::Matrix4d M_, Minv_;
  std::vector<HalfSpace> clip_;
};

}  // namespace qacc
