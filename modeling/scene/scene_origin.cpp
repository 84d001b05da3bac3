#include "modeling/scene/scene_origin.h"

#include <cmath>

namespace qacc {

Eigen::Vector3d sceneOrigin(const Camera& camera) {
  double scale = (camera.target - camera.eye).norm();
  if (camera.type == Camera::Type::Orthographic) scale = std::max(scale, camera.height);
  if (!(scale > 0) || !std::isfinite(scale)) return Eigen::Vector3d::Zero();
  const double grid = std::ldexp(1.0, int(std::ceil(std::log2(scale))) + 4);
  Eigen::Vector3d origin;
  for (int i = 0; i < 3; ++i) origin[i] = std::nearbyint(camera.target[i] / grid) * grid;
  return origin.allFinite() ? origin : Eigen::Vector3d::Zero();
}

}  // namespace qacc
