// Shading shared by every renderer (design §2), so that comparisons measure geometry:
// ambient + per light (Lambert + Blinn-Phong), material colour, two-sided (a back face is
// lit with the flipped normal), computed in linear RGB, output 8-bit sRGB.
#pragma once
#include <array>
#include <cstdint>

#include <Eigen/Dense>

#include "modeling/scene/scene.h"

namespace qacc {

// Linear RGB radiance at world point p with (unnormalised) normal n.
Eigen::Vector3d shadeLinear(const Scene& scene, const Material& m, const Eigen::Vector3d& p,
                            const Eigen::Vector3d& n);
// Linear [0, 1] → 8-bit sRGB (clamped, IEC 61966-2-1 transfer, rounded to nearest).
std::array<std::uint8_t, 3> toSrgb8(const Eigen::Vector3d& linear);
std::uint8_t linearToSrgb8(double v);

}  // namespace qacc
