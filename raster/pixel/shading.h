// Shading shared by every renderer (design §2), so that comparisons measure geometry:
// ambient + per light (Lambert + Blinn-Phong), material colour, two-sided (a back face is
// lit with the flipped normal), computed in linear RGB, output 8-bit sRGB.
#pragma once
#include <array>
#include <cstdint>

#include <Eigen/Dense>

#include "modeling/scene/scene.h"
#include "raster/pixel/srgb_encoding.h"  // the output encoding (toSrgb8)

namespace qacc {

// Linear RGB radiance at world point p with (unnormalised) normal n.
Eigen::Vector3d shadeLinear(const Scene& scene, const Material& m, const Eigen::Vector3d& p,
                            const Eigen::Vector3d& n);

}  // namespace qacc
