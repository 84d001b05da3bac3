#include "modeling/geometry/placed_exact_surface.h"

#include <algorithm>
#include <stdexcept>

#include "modeling/algebraic/algebraic_surface.h"

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

namespace {

struct MeshVertex {
  Eigen::Vector3d p, n;
};

// Sutherland-Hodgman clipping of a convex polygon by one half-space. The cut point of an
// edge is computed from its lexicographically smaller end, so the two triangles sharing
// the edge get the same point.
std::vector<MeshVertex> clipByHalfSpace(const std::vector<MeshVertex>& poly, const HalfSpace& h) {
  std::vector<MeshVertex> out;
  for (std::size_t i = 0; i < poly.size(); ++i) {
    const MeshVertex& a = poly[i];
    const MeshVertex& b = poly[(i + 1) % poly.size()];
    const bool ka = h.contains(a.p), kb = h.contains(b.p);
    if (ka) out.push_back(a);
    if (ka == kb) continue;
    const bool aFirst = std::lexicographical_compare(a.p.data(), a.p.data() + 3, b.p.data(), b.p.data() + 3);
    const MeshVertex& u = aFirst ? a : b;
    const MeshVertex& w = aFirst ? b : a;
    const double gu = h.eval(u.p), gw = h.eval(w.p);
    const double t = std::clamp(gu / (gu - gw), 0.0, 1.0);
    const Eigen::Vector3d n = u.n + t * (w.n - u.n);
    out.push_back({u.p + t * (w.p - u.p), n.squaredNorm() > 0.0 ? Eigen::Vector3d(n.normalized()) : u.n});
  }
  return out;
}

}  // namespace

ExactSurfaceMesh PlacedExactSurface::tessellate(std::size_t triangles) const {
  ExactSurfaceMesh in = inner_->tessellate(triangles);
  ExactSurfaceMesh out;
  out.grid = in.grid;
  const Eigen::Matrix3d A = M_.topLeftCorner<3, 3>();
  const double stretch = A.jacobiSvd().singularValues()(0);
  out.max_error = in.max_error * stretch;
  out.mean_error = in.mean_error * stretch;
  if (clip_.empty()) {
    out.positions = std::move(in.positions);
    out.normals = std::move(in.normals);
    out.triangles = std::move(in.triangles);
  } else {
    for (const auto& t : in.triangles) {
      std::vector<MeshVertex> poly;
      for (int v : t) poly.push_back({in.positions[std::size_t(v)], in.normals[std::size_t(v)]});
      for (std::size_t k = 0; k < clip_.size() && poly.size() >= 3; ++k) poly = clipByHalfSpace(poly, clip_[k]);
      if (poly.size() < 3) continue;
      const int base = int(out.positions.size());
      for (const auto& v : poly) {
        out.positions.push_back(v.p);
        out.normals.push_back(v.n);
      }
      for (int i = 1; i + 1 < int(poly.size()); ++i) out.triangles.push_back({base, base + i, base + i + 1});
    }
  }
  // Place: points by M, normals (covectors) by A⁻ᵀ; a mirror reverses the winding.
  const Eigen::Matrix3d normalMap = Minv_.topLeftCorner<3, 3>().transpose();
  for (auto& p : out.positions) p = (M_ * p.homogeneous()).head<3>();
  for (auto& n : out.normals) n = (normalMap * n).normalized();
  if (A.determinant() < 0)
    for (auto& t : out.triangles) std::swap(t[1], t[2]);
  return out;
}

}  // namespace qacc
