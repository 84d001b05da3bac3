// ViewVolume: the part of space a camera shows on a width x height image — the frustum
// (orthographic: box) 0 <= x, y <= width, height, 0 <= z <= 1 in window space — as
// half-spaces p·(X, 1) <= 0, widened by a margin (kMarginPixels on each side of the screen,
// a relative kMarginDepth in depth) so that rounding in the bounds it is tested against
// can never turn a visible piece into a culled one. The tests are conservative: they may
// answer "maybe" for a set that misses the volume but never "no" for one that meets it (a
// convex set misses it only when it lies wholly outside one of the half-spaces).
// Used by the modelers' view culling (loader/view_culling.h).
#pragma once
#include <array>
#include <vector>

#include <Eigen/Dense>
#include <Eigen/Geometry>

#include "modeling/scene/camera.h"

namespace qacc {

class ViewVolume {
 public:
  static constexpr double kMarginPixels = 2.0;
  static constexpr double kMarginDepth = 1e-6;

  // The view volume of `camera` on a width x height image, in world coordinates.
  static ViewVolume of(const Camera& camera, int width, int height);
  // The same volume in the coordinates of a frame placed in the world by `M` (a world point
  // is M · local): the planes become Mᵀ p.
  ViewVolume inFrame(const Eigen::Matrix4d& M) const;

  // False only when the convex hull of the points lies outside the volume.
  bool mayContain(const Eigen::Vector3d* points, std::size_t n) const;
  bool mayContain(const std::vector<Eigen::Vector3d>& points) const { return mayContain(points.data(), points.size()); }
  // False only when the box lies outside the volume.
  bool mayContain(const Eigen::AlignedBox3d& box) const;
  // False only when the ball of `radius` around `centre` lies outside the volume.
  bool mayContainBall(const Eigen::Vector3d& centre, double radius) const;

  const std::array<Eigen::Vector4d, 6>& planes() const { return planes_; }

 private:
  std::array<Eigen::Vector4d, 6> planes_;  // unit normals (xyz) in the frame they are given in
};

}  // namespace qacc
