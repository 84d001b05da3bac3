// Lights (design §2): ambient, directional (direction the light travels) and point.
#pragma once
#include <Eigen/Dense>

namespace qacc {

struct Light {
  enum class Type { Ambient, Directional, Point };
  Type type = Type::Directional;
  Eigen::Vector3d direction{0, 0, -1};  // directional: the direction light travels
  Eigen::Vector3d position{0, 0, 0};    // point
  Eigen::Vector3d color{1, 1, 1};       // linear RGB
};

}  // namespace qacc
