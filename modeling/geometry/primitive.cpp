#include "modeling/geometry/primitive.h"

namespace qacc {

Primitive Primitive::transformed(const Eigen::Matrix4d& M) const {
  const Eigen::Matrix4d Minv = M.inverse();
  Primitive out = *this;
  out.quadric = quadric.transformedByInverse(Minv);
  for (auto& h : out.clip) h = h.transformedByInverse(Minv);
  return out;
}

}  // namespace qacc
