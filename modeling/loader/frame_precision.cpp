#include "modeling/loader/frame_precision.h"

#include <algorithm>
#include <cmath>
#include <limits>

namespace qacc {

FramePrecision::FramePrecision(const Eigen::Matrix4d& placement, const ScreenView& view)
    : inverse_(Eigen::Matrix4d::Identity()), view_(view) {
  if (placement == Eigen::Matrix4d::Identity()) return;  // most objects of a large scene: no transform
  inverse_ = placement.inverse();
  const Eigen::JacobiSVD<Eigen::Matrix3d> svd(placement.topLeftCorner<3, 3>());
  stretch_ = svd.singularValues()[0];
}

double FramePrecision::pixels(const Eigen::AlignedBox3d& box) const {
  const double eps = std::numeric_limits<double>::epsilon();
  const Eigen::Vector3d local = (inverse_ * box.center().homogeneous()).head<3>();
  // The piece's half size in its own frame is at least its scene half size over the stretch.
  const double half = std::max(0.5 * box.diagonal().norm() / stretch_, std::numeric_limits<double>::min());
  const double distance = local.norm();
  // A piece within a few of its sizes of its frame's origin (every object placed by
  // `transform`) is uncertain by at most 25 ulps of its size: not worth the pixel scale.
  if (distance <= 4 * half) return 0;
  const double frameUnits = eps * (distance + half) * (distance + half) / half;
  return frameUnits * stretch_ * view_.maxPixelsPerUnit(box);
}

}  // namespace qacc
