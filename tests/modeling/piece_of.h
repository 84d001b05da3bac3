// A piece of a shipped scene written into a test: its quadric's matrix (column by column,
// as a scene's primitives hold it) and its clip planes, to 17 digits, so that a test can
// replay what the tessellation did with that piece without loading the scene.
#pragma once
#include <array>
#include <vector>

#include <Eigen/Dense>

#include "modeling/geometry/primitive.h"

namespace qacc::test {

inline Primitive pieceOf(const std::array<double, 16>& q, const std::vector<Eigen::Vector4d>& planes) {
  Primitive p;
  p.quadric = Quadric(Eigen::Map<const Eigen::Matrix4d>(q.data()));
  for (const auto& h : planes) p.clip.emplace_back(h);
  return p;
}

}  // namespace qacc::test
