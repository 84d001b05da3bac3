// Surface material: linear RGB colour and Blinn-Phong specular (design §2 shading).
#pragma once
#include <string>

#include <Eigen/Dense>

namespace qacc {

struct Material {
  std::string name = "default";
  Eigen::Vector3d color{0.8, 0.8, 0.8};  // linear RGB in [0, 1]; default light grey
  double specular = 0.2;                 // Blinn-Phong weight
  double shininess = 32.0;               // Blinn-Phong exponent
};

}  // namespace qacc
