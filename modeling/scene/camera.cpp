#include "modeling/scene/camera.h"

#include <cmath>

namespace qacc {

Eigen::Matrix4d Camera::view() const {
  const Eigen::Vector3d f = forward();
  const Eigen::Vector3d s = f.cross(up).normalized();
  const Eigen::Vector3d u = s.cross(f);
  Eigen::Matrix4d m = Eigen::Matrix4d::Identity();
  m.block<1, 3>(0, 0) = s.transpose();
  m.block<1, 3>(1, 0) = u.transpose();
  m.block<1, 3>(2, 0) = -f.transpose();
  m(0, 3) = -s.dot(eye);
  m(1, 3) = -u.dot(eye);
  m(2, 3) = f.dot(eye);
  return m;
}

Eigen::Matrix4d Camera::projection(double aspect) const {
  Eigen::Matrix4d p = Eigen::Matrix4d::Zero();
  if (type == Type::Perspective) {
    const double t = std::tan(fov_y_deg * M_PI / 360.0);
    p(0, 0) = 1.0 / (aspect * t);
    p(1, 1) = 1.0 / t;
    p(2, 2) = -(far + near) / (far - near);
    p(2, 3) = -2.0 * far * near / (far - near);
    p(3, 2) = -1.0;
  } else {
    const double t = height / 2.0;
    p(0, 0) = 1.0 / (aspect * t);
    p(1, 1) = 1.0 / t;
    p(2, 2) = -2.0 / (far - near);
    p(2, 3) = -(far + near) / (far - near);
    p(3, 3) = 1.0;
  }
  return p;
}

Eigen::Matrix4d Camera::viewport(int width, int height) {
  Eigen::Matrix4d v = Eigen::Matrix4d::Identity();
  v(0, 0) = width / 2.0;
  v(0, 3) = width / 2.0;
  v(1, 1) = -height / 2.0;
  v(1, 3) = height / 2.0;
  v(2, 2) = 0.5;
  v(2, 3) = 0.5;
  return v;
}

Eigen::Matrix4d Camera::worldToWindow(int width, int height) const {
  return viewport(width, height) * projection(double(width) / double(height)) * view();
}

Eigen::Vector3d Camera::toViewer(const Eigen::Vector3d& p) const {
  if (type == Type::Orthographic) return -forward();
  return (eye - p).normalized();
}

}  // namespace qacc
