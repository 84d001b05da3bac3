#include "modeling/geometry/primitive_bounds.h"

#include <cmath>

#include "modeling/geometry/piece_extent.h"

namespace qacc {
namespace {

constexpr double kFar = 1e12;  // a box this large stands for "unbounded"

}  // namespace

PrimitiveBounds primitiveBounds(const Primitive& prim) {
  PrimitiveBounds out;
  std::vector<Eigen::Vector4d> P;
  for (const auto& h : prim.clip) P.push_back(h.p);
  for (int a = 0; a < 3; ++a)
    for (double s : {-1.0, 1.0}) {
      Eigen::Vector4d p = Eigen::Vector4d::Zero();
      p[a] = s;
      p[3] = -kFar;
      P.push_back(p);
    }
  // Anchor the candidate lines near the piece: the centroid of the clip polytope's own
  // vertices (those not on the bounding box), the origin when it has none. A piece far from
  // the origin keeps its precision; an anchor on the bounding box would lose it.
  const std::vector<Eigen::Vector3d> vertices = polytopeVertices(P, nullptr);
  if (vertices.empty()) {
    out.empty = true;
    return out;
  }
  Eigen::Vector3d ref = Eigen::Vector3d::Zero();
  int own = 0;
  for (const auto& v : vertices)
    if (v.cwiseAbs().maxCoeff() < 0.5 * kFar) {
      ref += v;
      ++own;
    }
  if (own > 0) ref /= own;
  Eigen::AlignedBox3d box = pieceExtent(prim.quadric.Q, P, prim.solid, ref, 3);
  if (box.isEmpty()) {
    out.empty = true;
    return out;
  }
  // The candidates are exact up to rounding: widen by a relative 1e-9 of the extent so
  // that the box contains every point of the piece.
  const double pad = 1e-9 * (box.sizes().norm() + box.center().norm());
  box.min().array() -= pad;
  box.max().array() += pad;
  out.box = box;
  out.bounded = box.min().cwiseAbs().maxCoeff() < 0.5 * kFar && box.max().cwiseAbs().maxCoeff() < 0.5 * kFar;
  return out;
}

}  // namespace qacc
