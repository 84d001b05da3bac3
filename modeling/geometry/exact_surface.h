// ExactSurface: a non-quadric surface the reference renderer ray-casts exactly (e.g. an
// algebraic surface of degree n), so that quadric and triangle approximations of it can
// be measured against the truth. A scene object that has one (SceneObject::exact_surface
// >= 0) is drawn by the reference renderer from the exact surface instead of from its
// quadric pieces; the accelerator engines always draw the pieces. The facet renderers
// draw its triangles (tessellate) instead of the pieces' triangles.
#pragma once
#include <array>
#include <cstddef>
#include <vector>

#include <Eigen/Dense>

namespace qacc {

struct ExactHit {
  double t = 0;              // parameter along the segment, in [0, 1]
  Eigen::Vector3d normal;    // world-space normal (any length, any orientation)
};

// Triangles of an exact surface for the facet renderers (design §3.3).
struct ExactSurfaceMesh {
  std::vector<Eigen::Vector3d> positions;     // in the frame of intersect()
  std::vector<Eigen::Vector3d> normals;       // unit, per vertex: the surface's normal there
  std::vector<std::array<int, 3>> triangles;  // counter-clockwise seen from where the normals point
  int grid = 0;                               // cubes per axis of the marching-tetrahedra grid
  // Sampled two-sided distance between the triangles and the surface (same units).
  double max_error = 0, mean_error = 0;
};

class ExactSurface {
 public:
  virtual ~ExactSurface() = default;
  // First intersection of the world segment p0 → p1 (p(t) = p0 + t (p1 - p0)), t in [0, 1],
  // with the visible part of the surface. Must be deterministic and thread-safe.
  virtual bool intersect(const Eigen::Vector3d& p0, const Eigen::Vector3d& p1, ExactHit& hit) const = 0;
  // World-space axis-aligned bounds of the visible part (for screen bounding boxes).
  virtual Eigen::AlignedBox3d bounds() const = 0;
  // About `triangles` triangles of the visible part, vertices on the surface.
  virtual ExactSurfaceMesh tessellate(std::size_t triangles) const = 0;
};

}  // namespace qacc
