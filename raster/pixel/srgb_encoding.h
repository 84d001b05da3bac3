// sRGB encoding of the renderers' output (design §2): linear [0, 1] → 8-bit sRGB, the
// IEC 61966-2-1 transfer (12.92 v below 0.0031308, 1.055 v^(1/2.4) − 0.055 above), clamped
// and rounded to nearest.
//
// `linearToSrgb8Formula` evaluates that definition (a `pow` per channel); `linearToSrgb8`
// returns the same byte for every double without it. Above 0.0031308 the byte only changes
// where the formula's result crosses k + 1/2: a table holds, for every k, the smallest
// double at which the formula gives k or more (found once, by bisection over the doubles,
// with the formula itself), and a table indexed by the top bits of v starts the search
// next to v. An input within a relative 2^-32 of a boundary is handed to the formula: the
// formula's rounding errors (a few units in the last place of the result) can only move
// where it crosses k + 1/2 by far less than that, so outside the band both give the same
// byte even if the rounded formula is not monotonic at the boundary itself. NaN, infinities
// and values outside (0.0031308, 1] also go to the formula.
#pragma once
#include <array>
#include <cstdint>

#include <Eigen/Dense>

namespace qacc {

// The transfer as defined (std::pow); the reference for linearToSrgb8.
std::uint8_t linearToSrgb8Formula(double v);
// The same byte for every double, table-driven.
std::uint8_t linearToSrgb8(double v);
// Linear [0, 1] → 8-bit sRGB, per channel.
std::array<std::uint8_t, 3> toSrgb8(const Eigen::Vector3d& linear);

}  // namespace qacc
