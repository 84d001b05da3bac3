// Constructors of the natural and specific quadrics (thesis figs. 3.1-3.3, design §5).
// Each returns a Primitive oriented so that the solid interior is f <= 0, with the
// half-spaces that make it finite. Canonical shapes sit at the origin with their axis
// along +z; place them with Primitive::transformed and a placement matrix.
#pragma once
#include <Eigen/Dense>

#include "modeling/geometry/primitive.h"

namespace qacc {

// Sphere |x - c|² - r² <= 0.
Primitive makeSphere(const Eigen::Vector3d& center, double radius);
// Axis-aligned ellipsoid with semi-axes `radii`.
Primitive makeEllipsoid(const Eigen::Vector3d& center, const Eigen::Vector3d& radii);
// Circular cylinder between two points (clipped by the two end planes).
Primitive makeCylinder(const Eigen::Vector3d& base, const Eigen::Vector3d& top, double radius);
// Circular cone with its apex at `apex` and a disc of `radius` at `base`.
Primitive makeCone(const Eigen::Vector3d& apex, const Eigen::Vector3d& base, double radius);
// Elliptic paraboloid x²/rx² + y²/ry² <= z/h, for 0 <= z <= h (radii at the top rim).
Primitive makeParaboloid(double rx, double ry, double height);
// Hyperboloid of one sheet x²/a² + y²/b² - z²/c² <= 1, |z| <= height/2.
Primitive makeHyperboloid1(const Eigen::Vector3d& radii, double height);
// Hyperboloid of two sheets x²/a² + y²/b² - z²/c² <= -1, |z| <= height/2.
Primitive makeHyperboloid2(const Eigen::Vector3d& radii, double height);
// Hyperbolic paraboloid x²/a² - y²/b² <= z, clipped to |x|, |y| <= extent.
Primitive makeHyperbolicParaboloid(double a, double b, double extent);
// Elliptic cylinder x²/a² + y²/b² <= 1 along z, |z| <= height/2.
Primitive makeEllipticCylinder(double a, double b, double height);
// Hyperbolic cylinder x²/a² - y²/b² >= 1 (two sheets) along z, |y|, |z| clipped.
Primitive makeHyperbolicCylinder(double a, double b, double extent, double height);
// Parabolic cylinder x² <= 2 p y along z, clipped to y <= extent and |z| <= height/2.
Primitive makeParabolicCylinder(double p, double extent, double height);
// Plane through `point` with normal `n` (interior is the side opposite to n).
Primitive makePlane(const Eigen::Vector3d& point, const Eigen::Vector3d& normal);
// Triangle as a planar primitive clipped by its 3 edge half-spaces. The plane is oriented
// by the winding (a, b, c) (counter-clockwise seen from the front side).
Primitive makeTriangle(const Eigen::Vector3d& a, const Eigen::Vector3d& b, const Eigen::Vector3d& c);

// Rigid map taking the canonical +z axis at the origin to the segment from `from` along
// `axis` (any orthonormal completion).
Eigen::Matrix4d alignZ(const Eigen::Vector3d& from, const Eigen::Vector3d& axis);
// Placement transform of the scene format: scale, then rotate about X, Y, Z (degrees),
// then translate.
Eigen::Matrix4d placement(const Eigen::Vector3d& translate, const Eigen::Vector3d& rotate_deg,
                          const Eigen::Vector3d& scale);

}  // namespace qacc
