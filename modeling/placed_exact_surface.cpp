#include "modeling/placed_exact_surface.h"

#include <stdexcept>

#include "modeling/algebraic_surface.h"

namespace qacc {

PlacedExactSurface::PlacedExactSurface(std::shared_ptr<const ExactSurface> inner, const Eigen::Matrix4d& M,
                                       std::vector<HalfSpace> local_clip)
    : inner_(std::move(inner)), M_(M), clip_(std::move(local_clip)) {
  if (!inner_) throw std::invalid_argument("PlacedExactSurface: no surface");
  if (M.row(3) != Eigen::RowVector4d(0, 0, 0, 1))
    throw std::invalid_argument("PlacedExactSurface: the placement must be affine");
  Minv_ = M.inverse();
  if (!Minv_.allFinite()) throw std::invalid_argument("PlacedExactSurface: singular placement");
}

bool PlacedExactSurface::intersect(const Eigen::Vector3d& p0, const Eigen::Vector3d& p1, ExactHit& hit) const {
  // Affine maps keep the segment parameter.
  const Eigen::Vector3d q0 = (Minv_ * p0.homogeneous()).head<3>();
  const Eigen::Vector3d q1 = (Minv_ * p1.homogeneous()).head<3>();
  double t0 = 0.0, t1 = 1.0;
  const Eigen::Vector3d d = q1 - q0;
  if (!clipSegmentToHalfSpaces(clip_, q0, d, t0, t1)) return false;
  ExactHit h;
  if (!inner_->intersect(q0 + t0 * d, q0 + t1 * d, h)) return false;
  hit.t = t0 + h.t * (t1 - t0);
  // Normals are covectors: n_world = A⁻ᵀ n_local with A the linear part of M.
  hit.normal = Minv_.topLeftCorner<3, 3>().transpose() * h.normal;
  return true;
}

Eigen::AlignedBox3d PlacedExactSurface::bounds() const {
  const Eigen::AlignedBox3d b = inner_->bounds();
  Eigen::AlignedBox3d out;
  for (int c = 0; c < 8; ++c) {
    const Eigen::Vector3d p = b.corner(static_cast<Eigen::AlignedBox3d::CornerType>(c));
    out.extend((M_ * p.homogeneous()).head<3>());
  }
  return out;
}

}  // namespace qacc
