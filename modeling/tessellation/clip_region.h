// The region a primitive is tessellated over: its clip polyhedron, limited to the view
// frustum when it does not bound the piece (nothing outside the frustum can be seen), as
// the vertices of that polyhedron (exact enumeration of plane triples) and their box. Axial
// types need only the extent along their axis; planes their polygon.
#pragma once
#include <vector>

#include <Eigen/Dense>

#include "modeling/geometry/half_space.h"
#include "modeling/geometry/primitive.h"
#include "modeling/geometry/quadric_type.h"
#include "modeling/scene/camera.h"
#include "modeling/tessellation/quadric_frame.h"

namespace qacc::tess {

constexpr double kFar = 1e12;  // a box this large stands for "unbounded"

// Vertices of the polyhedron ∩ [−far, far]³ (exact enumeration of plane triples).
std::vector<Vector3d> polytopeVertices(const std::vector<HalfSpace>& planes, double far = kFar);
// All vertices well inside the kFar box.
bool finiteExtent(const std::vector<Vector3d>& verts);
// Axial extent [tmin, tmax] of the polyhedron's vertices along unit axis e from c.
void axialExtent(const std::vector<Vector3d>& verts, const Vector3d& c, const Vector3d& e, double& tmin, double& tmax);

struct TessellationRegion {
  bool empty = true;               // nothing (bounded) to draw
  std::vector<HalfSpace> planes;   // the primitive's clip planes, then the frustum's when added
  std::vector<Vector3d> vertices;  // of the region (none for an ellipsoid: it bounds itself)
  Eigen::AlignedBox3d box;
  double diag = 1.0;               // of the box
};
// `q` is the normalised quadric, `f` and `ltol` its axial frame (quadric_frame.h).
TessellationRegion tessellationRegion(const Primitive& prim, const Quadric& q, QuadricType type, const Frame& f,
                                      double ltol, const Camera* camera, double aspect);

}  // namespace qacc::tess
