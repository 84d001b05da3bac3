// World-space axis-aligned bounds of a primitive: the surface's own extent when it is
// bounded (an ellipsoid: tangent planes x = t satisfy πᵀ Q⁻¹ π = 0 for π = (1, 0, 0, −t)),
// intersected with the extent of its clip polyhedron (vertices enumerated exactly).
// `bounded` is false when neither limits the primitive in some direction.
#pragma once
#include <Eigen/Geometry>

#include "modeling/geometry/primitive.h"

namespace qacc {

struct PrimitiveBounds {
  Eigen::AlignedBox3d box;  // valid when bounded
  bool bounded = false;
  bool empty = false;       // the clip polyhedron is empty
};

PrimitiveBounds primitiveBounds(const Primitive& prim);

}  // namespace qacc
