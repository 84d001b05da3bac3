#include "modeling/scene/screen_view.h"

#include <algorithm>
#include <cmath>

namespace qacc {

ScreenView::ScreenView(const Camera& cam, int w, int h)
    : camera(cam), width(w), height(h), view(cam.view()), window(cam.worldToWindow(w, h)) {
  if (cam.type == Camera::Type::Perspective)
    focal = double(h) / (2.0 * std::tan(cam.fov_y_deg * M_PI / 360.0));
  else
    focal = double(h) / cam.height;
}

double ScreenView::pixelsPerUnit(const Eigen::Vector3d& p) const {
  if (camera.type == Camera::Type::Orthographic) return focal;
  const Eigen::Vector3d e = (view * p.homogeneous()).head<3>();
  const double Z = std::max(-e.z(), camera.near);
  return focal * std::max(e.norm(), Z) / (Z * Z);
}

double ScreenView::maxPixelsPerUnit(const Eigen::AlignedBox3d& box) const {
  if (camera.type == Camera::Type::Orthographic || box.isEmpty()) return focal;
  // Eye-space box of the eight corners: the nearest depth and the farthest distance bound
  // f |p| / Z² from above.
  double zmin = 1e300, dmax = 0;
  for (int c = 0; c < 8; ++c) {
    const Eigen::Vector3d e = (view * box.corner(Eigen::AlignedBox3d::CornerType(c)).homogeneous()).head<3>();
    zmin = std::min(zmin, -e.z());
    dmax = std::max(dmax, e.norm());
  }
  const double Z = std::max(zmin, camera.near);
  return focal * std::max(dmax, Z) / (Z * Z);
}

bool ScreenView::inFront(const Eigen::Vector3d& p) const {
  return -(view * p.homogeneous()).z() >= camera.near;
}

Eigen::Vector2d ScreenView::project(const Eigen::Vector3d& p) const {
  const Eigen::Vector4d w = window * p.homogeneous();
  return w.head<2>() / w.w();
}

bool ScreenView::onScreen(const Eigen::Vector3d& p, double margin) const {
  const Eigen::Vector4d w = window * p.homogeneous();
  if (!(w.w() > 0)) return false;
  const Eigen::Vector3d x = w.head<3>() / w.w();
  return x.z() >= 0 && x.z() <= 1 && x.x() >= -margin && x.x() <= width + margin && x.y() >= -margin &&
         x.y() <= height + margin;
}

bool ScreenView::boxOnScreen(const Eigen::AlignedBox3d& box, double margin) const {
  if (box.isEmpty()) return false;
  Eigen::AlignedBox2d proj;
  double zmin = 1e300, zmax = -1e300;
  int behind = 0;
  for (int c = 0; c < 8; ++c)
    if (!inFront(box.corner(Eigen::AlignedBox3d::CornerType(c)))) ++behind;
  if (behind == 8) return false;  // wholly nearer than the near plane or behind the eye
  if (behind > 0) return true;    // reaches across the near plane: keep it
  for (int c = 0; c < 8; ++c) {
    const Eigen::Vector4d w = window * box.corner(Eigen::AlignedBox3d::CornerType(c)).homogeneous();
    const Eigen::Vector3d x = w.head<3>() / w.w();
    proj.extend(x.head<2>());
    zmin = std::min(zmin, x.z());
    zmax = std::max(zmax, x.z());
  }
  if (zmax < 0 || zmin > 1) return false;
  return proj.max().x() >= -margin && proj.min().x() <= width + margin && proj.max().y() >= -margin &&
         proj.min().y() <= height + margin;
}

}  // namespace qacc
