#include "modeling/geometry/primitive_bounds.h"

#include <cmath>

#include <Eigen/Cholesky>

#include "modeling/geometry/piece_extent.h"

namespace qacc {
namespace {

constexpr double kFar = 1e12;  // a box this large stands for "unbounded"

// The candidates are exact up to rounding: widen by a relative 1e-9 of the extent so that
// the box contains every point of the piece.
void pad(Eigen::AlignedBox3d& box) {
  const double pad = 1e-9 * (box.sizes().norm() + box.center().norm());
  box.min().array() -= pad;
  box.max().array() += pad;
}

// An unclipped ellipsoid (every atom of a molecule, most spheres of a large scene) in closed
// form: with Q = [A b; bᵀ c] and A positive definite, the centre is x₀ = −A⁻¹b, the surface is
// (x − x₀)ᵀA(x − x₀) = k with k = −f(x₀) = bᵀA⁻¹b − c, and its extent along axis i is
// √(k (A⁻¹)ᵢᵢ). A solid's interior (f <= 0) has the same box. False when the shortcut does not
// apply (clipped, not an ellipsoid, a solid outside a negative-definite one, a point).
bool ellipsoidBounds(const Primitive& prim, PrimitiveBounds& out) {
  if (!prim.clip.empty()) return false;
  Eigen::Matrix4d Q = prim.quadric.Q;
  Eigen::LLT<Eigen::Matrix3d> llt(Q.topLeftCorner<3, 3>());
  if (llt.info() != Eigen::Success) {
    if (prim.solid) return false;  // −Q would swap inside and outside
    Q = -Q;
    llt.compute(Q.topLeftCorner<3, 3>());
    if (llt.info() != Eigen::Success) return false;
  }
  const Eigen::Matrix3d Ainv = llt.solve(Eigen::Matrix3d::Identity());
  const Eigen::Vector3d b = Q.topRightCorner<3, 1>();
  const Eigen::Vector3d x0 = -(Ainv * b);
  const double k = b.dot(Ainv * b) - Q(3, 3);
  if (!Ainv.allFinite() || !x0.allFinite() || !std::isfinite(k)) return false;
  if (!(k > 0)) {
    if (k < 0) out.empty = true;  // no real point
    return k < 0;
  }
  const Eigen::Vector3d half = (k * Ainv.diagonal()).cwiseMax(0).cwiseSqrt();
  Eigen::AlignedBox3d box(x0 - half, x0 + half);
  pad(box);
  out.box = box;
  out.bounded = box.min().cwiseAbs().maxCoeff() < 0.5 * kFar && box.max().cwiseAbs().maxCoeff() < 0.5 * kFar;
  return true;
}

}  // namespace

PrimitiveBounds primitiveBounds(const Primitive& prim) {
  PrimitiveBounds out;
  if (ellipsoidBounds(prim, out)) return out;
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
  pad(box);
  out.box = box;
  out.bounded = box.min().cwiseAbs().maxCoeff() < 0.5 * kFar && box.max().cwiseAbs().maxCoeff() < 0.5 * kFar;
  return out;
}

void recordWorldBox(Primitive& prim, const PrimitiveBounds& bounds) {
  prim.known_box = {};
  if (!bounds.bounded || bounds.empty) return;
  prim.known_box.box = bounds.box;
  prim.known_box.key = prim.shapeKey();
}

const Eigen::AlignedBox3d* knownWorldBox(const Primitive& prim) {
  if (prim.known_box.key == 0 || prim.known_box.key != prim.shapeKey()) return nullptr;
  return &prim.known_box.box;
}

}  // namespace qacc
