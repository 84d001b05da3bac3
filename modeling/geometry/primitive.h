// Primitive: the contract between modelers and renderers (design §2).
// A quadric, the half-spaces of its clip polyhedron, surface or solid display, a material
// index into Scene::materials and the index of the scene object it came from.
// Triangles are primitives too: a plane clipped by its 3 edge half-spaces.
#pragma once
#include <cstdint>
#include <vector>

#include <Eigen/Geometry>

#include "modeling/geometry/half_space.h"
#include "modeling/geometry/quadric.h"

namespace qacc {

// A world box known to contain a primitive's piece, with the key of the primitive it was
// found for (Primitive::shapeKey; 0: none). primitive_bounds.h records and reads it.
struct KnownWorldBox {
  std::uint64_t key = 0;
  Eigen::AlignedBox3d box;
};

struct Primitive {
  Quadric quadric;
  std::vector<HalfSpace> clip;
  bool solid = false;  // show caps on the clip planes (interior f <= 0)
  int material = 0;
  int object = 0;
  // The piece's world bounds as the scene loader found them (recordWorldBox), which the
  // window-space setup reads (knownWorldBox) to leave out the view volume's faces the piece
  // cannot reach. Valid only while quadric, clip and solid are unchanged: a primitive edited
  // after loading no longer matches its key and is set up in full.
  KnownWorldBox known_box;

  // A 64-bit key of quadric, clip and solid (their bits), never 0.
  std::uint64_t shapeKey() const;
  // All points of the primitive after points move as X' = M X.
  Primitive transformed(const Eigen::Matrix4d& M) const;
  // True when the quadratic part is zero: a plane (facet) that needs no square root.
  bool isPlanar() const { return quadric.Q.topLeftCorner<3, 3>().cwiseAbs().maxCoeff() == 0.0; }
};

}  // namespace qacc
