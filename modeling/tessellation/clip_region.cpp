#include "modeling/tessellation/clip_region.h"

#include <algorithm>
#include <cmath>

#include "modeling/geometry/primitive_bounds.h"
#include "modeling/tessellation/tessellation.h"

namespace qacc {

std::vector<HalfSpace> frustumHalfSpaces(const Camera& camera, double aspect) {
  const Matrix4d M = camera.projection(aspect) * camera.view();
  std::vector<HalfSpace> out;
  // Sides slightly widened so that geometry reaching the image border is kept whole.
  const double side = 1.05;
  for (int r = 0; r < 2; ++r) {
    out.emplace_back(Vector4d(M.row(r).transpose() - side * M.row(3).transpose()));
    out.emplace_back(Vector4d(-M.row(r).transpose() - side * M.row(3).transpose()));
  }
  // Near and far just inside the depth range (1e-5 of it): a solid's cap on them (a leaf of
  // a csg object bounded by the frustum, tessellation.h) is drawn, not clipped by GL, and
  // its depth differs from the cleared depth buffer's 1 (the GL_EQUAL pass of
  // facet_csg_draw.h would otherwise colour the far cap over the background).
  const double depth = 1 - 1e-5;
  out.emplace_back(Vector4d(M.row(2).transpose() - depth * M.row(3).transpose()));
  out.emplace_back(Vector4d(-M.row(2).transpose() - depth * M.row(3).transpose()));
  return out;
}

}  // namespace qacc

namespace qacc::tess {

// Vertices of the polyhedron ∩ [−kFar, kFar]³ (exact enumeration of plane triples).
std::vector<Vector3d> polytopeVertices(const std::vector<HalfSpace>& planes, double far) {
  std::vector<Vector4d> P;
  for (const auto& h : planes) P.push_back(h.p);
  for (int a = 0; a < 3; ++a)
    for (double s : {-1.0, 1.0}) {
      Vector4d p = Vector4d::Zero();
      p[a] = s;
      p[3] = -far;
      P.push_back(p);
    }
  std::vector<Vector3d> out;
  const std::size_t n = P.size();
  for (std::size_t i = 0; i < n; ++i)
    for (std::size_t j = i + 1; j < n; ++j)
      for (std::size_t k = j + 1; k < n; ++k) {
        Matrix3d A;
        A << P[i].head<3>().transpose(), P[j].head<3>().transpose(), P[k].head<3>().transpose();
        const double scale = P[i].head<3>().norm() * P[j].head<3>().norm() * P[k].head<3>().norm();
        if (!(std::abs(A.determinant()) > 1e-12 * scale)) continue;
        const Vector3d v = A.inverse() * Vector3d(-P[i][3], -P[j][3], -P[k][3]);
        bool ok = v.allFinite();
        for (std::size_t m = 0; ok && m < n; ++m) {
          const double mag = P[m].head<3>().cwiseAbs().dot(v.cwiseAbs()) + std::abs(P[m][3]);
          if (P[m].dot(v.homogeneous()) > 1e-9 * mag) ok = false;
        }
        if (ok) out.push_back(v);
      }
  return out;
}

bool finiteExtent(const std::vector<Vector3d>& verts) {
  if (verts.empty()) return false;
  for (const auto& v : verts)
    if (v.cwiseAbs().maxCoeff() > 0.5 * kFar) return false;
  return true;
}

// Axial extent [tmin, tmax] of the polyhedron's vertices along unit axis e from c.
void axialExtent(const std::vector<Vector3d>& verts, const Vector3d& c, const Vector3d& e, double& tmin, double& tmax) {
  tmin = 1e300;
  tmax = -1e300;
  for (const auto& v : verts) {
    const double t = e.dot(v - c);
    tmin = std::min(tmin, t);
    tmax = std::max(tmax, t);
  }
}

TessellationRegion tessellationRegion(const Primitive& prim, const Quadric& q, QuadricType type, const Frame& f,
                                      double ltol, const Camera* camera, double aspect) {
  TessellationRegion region;
  const bool axial = type == QuadricType::EllipticCylinder || type == QuadricType::EllipticParaboloid ||
                     type == QuadricType::EllipticCone || type == QuadricType::HyperboloidOneSheet ||
                     type == QuadricType::HyperboloidTwoSheets;

  // The region to tessellate: the clip polyhedron, limited to the view frustum when it does
  // not bound the piece. Axial types need only the axial extent; planes their polygon.
  std::vector<HalfSpace> planes = prim.clip;
  auto regionVertices = [&](const std::vector<HalfSpace>& pl, double far = kFar) {
    std::vector<HalfSpace> ext = pl;
    if (type == QuadricType::Plane) {
      const Vector4d pp = q.Q.col(3) * 2.0;  // f = 2 g·x + J for a plane: (2g, J)
      Vector4d plane(pp.x(), pp.y(), pp.z(), q.Q(3, 3));
      ext.emplace_back(plane);
      ext.emplace_back(Vector4d(-plane));
    }
    return polytopeVertices(ext, far);
  };
  std::vector<HalfSpace> bounding;  // extra planes that only bound the region (not clipped)
  if (type == QuadricType::EllipticParaboloid) {
    // The surface lies on one side of its vertex's tangent plane: t <= tv when h > 0.
    const Vector3d c = partialCentre(f, ltol);
    const double h = f.V.col(2).dot(f.g);
    const double tv = -evalFrame(f, c) / (2 * h);
    const Vector3d e = (h > 0 ? 1.0 : -1.0) * f.V.col(2);
    bounding.push_back(HalfSpace::fromPointNormal(c + tv * f.V.col(2), e));
  }
  auto withBounding = [&](std::vector<HalfSpace> pl) {
    pl.insert(pl.end(), bounding.begin(), bounding.end());
    return pl;
  };
  std::vector<Vector3d> verts;
  bool bounded = true;
  if (type != QuadricType::Ellipsoid) {
    verts = regionVertices(withBounding(planes));
    if (axial) {
      double t0, t1;
      axialExtent(verts, Vector3d::Zero(), f.V.col(2), t0, t1);
      bounded = !verts.empty() && std::abs(t0) < 0.5 * kFar && std::abs(t1) < 0.5 * kFar;
    } else {
      bounded = finiteExtent(verts);
    }
    if (!bounded && camera && !verts.empty()) {
      for (const auto& h : frustumHalfSpaces(*camera, aspect)) planes.push_back(h);
      verts = regionVertices(withBounding(planes));
      bounded = finiteExtent(verts);
    }
    if (verts.empty() || !bounded) return region;  // nothing (bounded) to draw
    if (axial) {
      // Vertices on a 1e12 box carry ~1e-4 of rounding into the axial extent: enumerate
      // again in a box just large enough to hold the surface over that extent.
      const Vector3d c = partialCentre(f, ltol);
      double t0, t1;
      axialExtent(verts, c, f.V.col(2), t0, t1);
      const double T = std::max(std::abs(t0), std::abs(t1));
      const double lmin = std::min(std::abs(f.lambda[0]), std::abs(f.lambda[1]));
      const double R = std::sqrt((std::abs(evalFrame(f, c)) + std::abs(f.lambda[2]) * T * T +
                                  2 * std::abs(f.V.col(2).dot(f.g)) * T) / lmin);
      const double far = 4 * (1 + c.norm() + R + T);
      if (far < 0.5 * kFar) verts = regionVertices(withBounding(planes), far);
      if (verts.empty()) return region;
    }
  }
  Eigen::AlignedBox3d box;
  for (const auto& v : verts) box.extend(v);
  if (type == QuadricType::Ellipsoid) box = primitiveBounds(prim).box;
  const double diag = box.isEmpty() ? 1.0 : box.sizes().norm();
  region.empty = false;
  region.planes = std::move(planes);
  region.vertices = std::move(verts);
  region.box = box;
  region.diag = diag;
  return region;
}

}  // namespace qacc::tess
