// World-space axis-aligned bounds of a primitive: the exact extent of its clipped piece —
// (surface ∩ clip polyhedron), or ({f <= 0} ∩ clip polyhedron) for a solid — by the
// Lagrange candidates of piece_extent.h, inside a box of ±kFar that stands for "unbounded".
// A primitive is unbounded only when its clipped piece is (in some direction).
#pragma once
#include <Eigen/Geometry>

#include "modeling/geometry/primitive.h"

namespace qacc {

struct PrimitiveBounds {
  Eigen::AlignedBox3d box;  // the piece's extent; valid in every direction when bounded
  bool bounded = false;     // the piece is bounded in every direction
  bool empty = false;       // the piece is empty (nothing to draw)
};

PrimitiveBounds primitiveBounds(const Primitive& prim);

// Keeps `bounds` with the primitive (Primitive::known_box) when bounded and not empty, keyed
// by its shape, for knownWorldBox.
void recordWorldBox(Primitive& prim, const PrimitiveBounds& bounds);
// The recorded box when the primitive is still the one it was recorded for, else null.
const Eigen::AlignedBox3d* knownWorldBox(const Primitive& prim);

}  // namespace qacc
