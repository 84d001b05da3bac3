// Piecewise quadrics of revolution from a profile polyline (thesis §4.2.3, (4.3)-(4.7)).
//
// A quadric of revolution about the local z axis is A(x² + y²) + C z² + Iz z + J = 0
// (4.3; Iz is the full z coefficient, i.e. twice the I of (3.1)). Its profile in the plane
// x = 0 is A y² + C z² + Iz z + J = 0 (4.4); three profile points (r_i, z_i) determine it
// by the determinant (4.5), whose cofactors are (4.6) (profileThroughThreePoints).
// Because the profile has no r or rz term, r² is a quadratic function of z wherever
// A != 0: every plane z = k cuts the surface in at most one circle, so a piece clipped to
// the slab between two planes z = const is exactly one band of the surface.
//
// Joins (the profile z must be strictly monotone):
//  - "G0": 2n + 1 profile points give n quadrics; quadric k interpolates points 2k, 2k+1,
//    2k+2 (4.5)-(4.6) and is clipped to the slab [z_2k, z_2k+2]; adjacent quadrics share
//    their end point, hence a circle (G0).
//  - "G1": m profile points give m - 1 quadrics; quadric k interpolates points k and k+1
//    and has at point k the profile normal (2A y, 2C z + Iz) (4.7) of quadric k - 1
//    (collinear normals ⇒ G1 along the shared circle): a C1 quadratic spline of r² in z.
//    One degree of freedom remains (the first quadric's slope); it is chosen to minimise
//    Σ (a_k+1 - a_k)² (a_k the z² coefficient of r² on slab k: the jumps of (r²)'' at the
//    joins), which keeps the spline from oscillating and reproduces a single quadric
//    exactly when all points lie on one. (The thesis leaves the choice to the user;
//    fixing the first quadric by three points instead makes the recurrence oscillate.)
// Each slab plane z = z_j is built once (HalfSpace keeping z <= z_j) and the piece above it
// uses its opposite(), so exactly one of two adjacent pieces owns the shared circle.
// A piece whose r² becomes negative inside its slab would leave a gap in the surface and
// is refused (std::invalid_argument).
#pragma once
#include <string>
#include <vector>

#include <Eigen/Dense>

#include "modeling/loader/object_registry.h"
#include "modeling/loader/view_cull_count.h"
#include "modeling/geometry/primitive.h"
#include "modeling/geometry/quadric.h"

namespace qacc {

struct ProfilePoint {
  double r = 0;  // distance from the axis (>= 0)
  double z = 0;  // position along the axis
};

// Profile coefficients (A, C, Iz, J) of A r² + C z² + Iz z + J.
struct RevolutionProfile {
  double A = 0, C = 0, Iz = 0, J = 0;
  double eval(double r, double z) const { return A * r * r + C * z * z + Iz * z + J; }
  // Profile normal (4.7): (2 A r, 2 C z + Iz).
  Eigen::Vector2d normal(double r, double z) const { return {2 * A * r, 2 * C * z + Iz}; }
  // The quadric of revolution about z, oriented so that the axis side is f <= 0 (A > 0).
  Quadric quadric() const;
  // r² on the profile at height z (= -(C z² + Iz z + J) / A).
  double radiusSquared(double z) const { return -(C * z * z + Iz * z + J) / A; }
};

// (4.5)-(4.6): the profile through three points (cofactor expansion of the determinant).
RevolutionProfile profileThroughThreePoints(const ProfilePoint& p1, const ProfilePoint& p2,
                                            const ProfilePoint& p3);
// The profile through p1 and p2 whose normal at p1 is parallel to n1 (G1 continuation).
RevolutionProfile profileThroughTwoPointsWithNormal(const ProfilePoint& p1, const ProfilePoint& p2,
                                                    const Eigen::Vector2d& n1);

enum class RevolutionJoin { G0, G1 };

struct RevolutionPiece {
  RevolutionProfile profile;
  double z0 = 0, z1 = 0;  // slab, z0 < z1
};

// The profile pieces for the given join (see above). Throws std::invalid_argument on too
// few points, the wrong count for G0 (must be odd), non-monotone z, negative r, or a piece
// whose r² goes negative in its slab.
std::vector<RevolutionPiece> revolutionPieces(const std::vector<ProfilePoint>& profile, RevolutionJoin join);

// The pieces as primitives about the axis through `origin` along `direction` (local z maps
// onto it), clipped between consecutive profile planes (shared planes built once). With a
// `view` (view culling, ObjectContext::view), a piece whose box — its slab by its largest
// radius about the axis — misses the view is not built (counted in `count`).
std::vector<Primitive> revolutionPrimitives(const std::vector<ProfilePoint>& profile, RevolutionJoin join,
                                            const Eigen::Vector3d& origin = Eigen::Vector3d::Zero(),
                                            const Eigen::Vector3d& direction = Eigen::Vector3d::UnitZ(),
                                            const ViewVolume* view = nullptr, ViewCullCount* count = nullptr);

// Scene builder for "revolution": {"profile": [[r, z], ...], "join": "G0" | "G1" (default
// "G0"), "axis": {"origin": [x, y, z], "direction": [x, y, z]} (default the z axis)}.
std::vector<Primitive> buildRevolution(const JsonNode& o, ObjectContext& ctx);

}  // namespace qacc
