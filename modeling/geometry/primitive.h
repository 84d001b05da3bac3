// Primitive: the contract between modelers and renderers (design §2).
// A quadric, the half-spaces of its clip polyhedron, surface or solid display, a material
// index into Scene::materials and the index of the scene object it came from.
// Triangles are primitives too: a plane clipped by its 3 edge half-spaces.
#pragma once
#include <vector>

#include "modeling/geometry/half_space.h"
#include "modeling/geometry/quadric.h"

namespace qacc {

struct Primitive {
  Quadric quadric;
  std::vector<HalfSpace> clip;
  bool solid = false;  // show caps on the clip planes (interior f <= 0)
  int material = 0;
  int object = 0;

  // All points of the primitive after points move as X' = M X.
  Primitive transformed(const Eigen::Matrix4d& M) const;
  // True when the quadratic part is zero: a plane (facet) that needs no square root.
  bool isPlanar() const { return quadric.Q.topLeftCorner<3, 3>().cwiseAbs().maxCoeff() == 0.0; }
};

}  // namespace qacc
