#include "modeling/scene/view_volume.h"

#include <cmath>

namespace qacc {

namespace {

Eigen::Vector4d unitPlane(const Eigen::Vector4d& p) {
  const double n = p.head<3>().norm();
  return n > 0 ? Eigen::Vector4d(p / n) : p;
}

}  // namespace

ViewVolume ViewVolume::of(const Camera& camera, int width, int height) {
  // Window point (x, y, z) = (M X) / w with w > 0 inside the volume; each bound on x, y or z
  // is a linear inequality in X. Their conjunction already implies w > 0 (x >= -m and
  // x <= W + m force w >= 0), so the six half-spaces are the volume.
  const Eigen::Matrix4d M = camera.worldToWindow(width, height);
  const Eigen::RowVector4d x = M.row(0), y = M.row(1), z = M.row(2), w = M.row(3);
  const double m = kMarginPixels, dz = kMarginDepth;
  ViewVolume v;
  v.planes_[0] = unitPlane((-x - m * w).transpose());                 // x >= -m
  v.planes_[1] = unitPlane((x - (width + m) * w).transpose());       // x <= W + m
  v.planes_[2] = unitPlane((-y - m * w).transpose());                 // y >= -m
  v.planes_[3] = unitPlane((y - (height + m) * w).transpose());      // y <= H + m
  v.planes_[4] = unitPlane((-z - dz * w).transpose());                // z >= -dz
  v.planes_[5] = unitPlane((z - (1 + dz) * w).transpose());          // z <= 1 + dz
  return v;
}

ViewVolume ViewVolume::inFrame(const Eigen::Matrix4d& M) const {
  ViewVolume v;
  for (std::size_t i = 0; i < planes_.size(); ++i) v.planes_[i] = unitPlane(M.transpose() * planes_[i]);
  return v;
}

bool ViewVolume::mayContain(const Eigen::Vector3d* points, std::size_t n) const {
  if (n == 0) return false;
  for (const Eigen::Vector4d& p : planes_) {
    bool allOut = true;
    for (std::size_t i = 0; i < n && allOut; ++i) allOut = p.head<3>().dot(points[i]) + p[3] > 0;
    if (allOut) return false;
  }
  return true;
}

bool ViewVolume::mayContain(const Eigen::AlignedBox3d& box) const {
  if (box.isEmpty()) return false;
  for (const Eigen::Vector4d& p : planes_) {
    // The corner of the box that is lowest on the plane's normal.
    Eigen::Vector3d c;
    for (int a = 0; a < 3; ++a) c[a] = p[a] >= 0 ? box.min()[a] : box.max()[a];
    if (p.head<3>().dot(c) + p[3] > 0) return false;
  }
  return true;
}

bool ViewVolume::mayContainBall(const Eigen::Vector3d& centre, double radius) const {
  for (const Eigen::Vector4d& p : planes_)
    if (p.head<3>().dot(centre) + p[3] > std::fabs(radius)) return false;
  return true;
}

}  // namespace qacc
