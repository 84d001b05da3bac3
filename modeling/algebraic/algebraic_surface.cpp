#include "modeling/algebraic/algebraic_surface.h"

#include <algorithm>
#include <cmath>
#include <stdexcept>

#include "modeling/algebraic/bernstein_roots.h"
#include "modeling/algebraic/marching_tetrahedra.h"

namespace qacc {

AlgebraicSurface::AlgebraicSurface(Polynomial3 f, const Eigen::AlignedBox3d& box) : f_(std::move(f)), box_(box) {
  if (box_.isEmpty() || !box_.min().allFinite() || !box_.max().allFinite())
    throw std::invalid_argument("AlgebraicSurface: empty or non-finite box");
}

bool AlgebraicSurface::clipToBox(const Eigen::Vector3d& p0, const Eigen::Vector3d& d, double& t0, double& t1) const {
  t0 = 0.0;
  t1 = 1.0;
  for (int a = 0; a < 3; ++a) {
    if (d[a] == 0.0) {
      if (p0[a] < box_.min()[a] || p0[a] > box_.max()[a]) return false;
      continue;
    }
    double ta = (box_.min()[a] - p0[a]) / d[a];
    double tb = (box_.max()[a] - p0[a]) / d[a];
    if (ta > tb) std::swap(ta, tb);
    t0 = std::max(t0, ta);
    t1 = std::min(t1, tb);
    if (t0 > t1) return false;
  }
  return true;
}

bool clipSegmentToHalfSpaces(const std::vector<HalfSpace>& clip, const Eigen::Vector3d& p0,
                             const Eigen::Vector3d& d, double& t0, double& t1) {
  for (const HalfSpace& h : clip) {
    const double v0 = h.eval(p0);
    const double dv = h.p.head<3>().dot(d);  // value at t: v0 + t dv, keep <= 0
    if (dv == 0.0) {
      if (!h.keeps(v0)) return false;
      continue;
    }
    const double tc = -v0 / dv;
    if (dv > 0.0)
      t1 = std::min(t1, tc);
    else
      t0 = std::max(t0, tc);
    if (t0 > t1) return false;
  }
  return true;
}

bool AlgebraicSurface::intersect(const Eigen::Vector3d& p0, const Eigen::Vector3d& p1, ExactHit& hit) const {
  const Eigen::Vector3d d = p1 - p0;
  double t0, t1;
  if (!clipToBox(p0, d, t0, t1)) return false;
  const Eigen::Vector3d q0 = p0 + t0 * d;
  const Eigen::Vector3d dq = (t1 - t0) * d;
  double s;
  if (!firstBernsteinRoot(powerToBernstein(f_.alongLine(q0, dq)), s)) return false;
  hit.t = t0 + s * (t1 - t0);
  Eigen::Vector3d n = f_.gradient(p0 + hit.t * d);
  if (!(n.squaredNorm() > 0.0) || !n.allFinite()) n = -d;  // singular point: face the ray
  hit.normal = n;
  return true;
}

std::vector<double> AlgebraicSurface::allRoots(const Eigen::Vector3d& p0, const Eigen::Vector3d& p1) const {
  const Eigen::Vector3d d = p1 - p0;
  double t0, t1;
  if (!clipToBox(p0, d, t0, t1)) return {};
  std::vector<double> r = allBernsteinRoots(powerToBernstein(f_.alongLine(p0 + t0 * d, (t1 - t0) * d)));
  for (double& t : r) t = t0 + t * (t1 - t0);
  return r;
}

ExactSurfaceMesh AlgebraicSurface::tessellate(std::size_t triangles) const {
  ExactSurfaceMesh out;
  TriangleSoup soup = marchingTetrahedraOfSize(f_, box_, triangles, &out.grid);
  const FacetError e = facetError(f_, soup, box_);
  out.max_error = e.max;
  out.mean_error = e.mean;
  out.normals.resize(soup.vertices.size(), Eigen::Vector3d::Zero());
  // At a singular point (∇f = 0) the vertex takes the mean normal of its triangles.
  std::vector<Eigen::Vector3d> faceSum(soup.vertices.size(), Eigen::Vector3d::Zero());
  for (const auto& t : soup.triangles) {
    const Eigen::Vector3d& a = soup.vertices[std::size_t(t[0])];
    const Eigen::Vector3d n = (soup.vertices[std::size_t(t[1])] - a).cross(soup.vertices[std::size_t(t[2])] - a);
    for (int v : t) faceSum[std::size_t(v)] += n;
  }
  for (std::size_t i = 0; i < soup.vertices.size(); ++i) {
    const Eigen::Vector3d g = f_.gradient(soup.vertices[i]);
    const Eigen::Vector3d& n = g.squaredNorm() > 0.0 && g.allFinite() ? g : faceSum[i];
    out.normals[i] = n.squaredNorm() > 0.0 ? Eigen::Vector3d(n.normalized()) : Eigen::Vector3d(0, 0, 1);
  }
  out.positions = std::move(soup.vertices);
  out.triangles = std::move(soup.triangles);
  return out;
}

}  // namespace qacc
