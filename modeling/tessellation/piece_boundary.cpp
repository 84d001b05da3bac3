// A clipped piece's triangles against its region (piece_boundary.h).
#include "modeling/tessellation/piece_boundary.h"

#include <algorithm>
#include <cmath>

namespace qacc::tess {

namespace {

double roundingScale(const HalfSpace& h, const Eigen::Vector3d& x) {
  return 1e-9 * (h.p.head<3>().norm() * x.norm() + std::abs(h.p[3])) + 1e-300;
}

}  // namespace

bool onPlaneWithinRounding(const HalfSpace& h, const Eigen::Vector3d& x) {
  return std::abs(h.eval(x)) <= roundingScale(h, x);
}

PieceBoundary checkPieceBoundary(const TriangleMesh3& mesh, std::size_t surface, const std::vector<HalfSpace>& planes) {
  PieceBoundary out;
  TriangleMesh3 own;
  own.positions = mesh.positions;  // edgeUse reads positions and triangles only
  own.triangles.assign(mesh.triangles.begin(), mesh.triangles.begin() + std::ptrdiff_t(std::min(surface, mesh.size())));
  std::vector<bool> used(mesh.positions.size(), false);
  for (const auto& t : own.triangles)
    for (int k : t) used[std::size_t(k)] = true;
  for (std::size_t v = 0; v < mesh.positions.size(); ++v) {
    if (!used[v]) continue;
    const Eigen::Vector3d& x = mesh.positions[v];
    for (const HalfSpace& h : planes)
      if (h.eval(x) > roundingScale(h, x)) {
        ++out.outside;
        break;
      }
  }
  for (const OpenEdge& e : edgeUse(own).open) {
    const bool on = std::any_of(planes.begin(), planes.end(), [&](const HalfSpace& h) {
      return onPlaneWithinRounding(h, e.a) && onPlaneWithinRounding(h, e.b);
    });
    if (!on) ++out.off_plane_edges;
  }
  return out;
}

}  // namespace qacc::tess
