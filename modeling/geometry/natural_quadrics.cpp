#include "modeling/geometry/natural_quadrics.h"

#include <cmath>

namespace qacc {
namespace {

HalfSpace zBelow(double h) { return HalfSpace(Eigen::Vector4d(0, 0, 1, -h)); }   // z <= h
HalfSpace zAbove(double h) { return HalfSpace(Eigen::Vector4d(0, 0, -1, h)); }   // z >= h
HalfSpace axisSlab(int axis, double sign, double h) {  // sign * x_axis <= h
  Eigen::Vector4d p = Eigen::Vector4d::Zero();
  p[axis] = sign;
  p[3] = -h;
  return HalfSpace(p);
}

Primitive diagonal(double a, double b, double c, double j) {
  Primitive p;
  p.quadric = Quadric::fromCoefficients(a, b, c, 0, 0, 0, 0, 0, 0, j);
  return p;
}

}  // namespace

Eigen::Matrix4d alignZ(const Eigen::Vector3d& from, const Eigen::Vector3d& axis) {
  const Eigen::Vector3d z = axis.normalized();
  const Eigen::Vector3d helper = std::abs(z.x()) < 0.9 ? Eigen::Vector3d::UnitX() : Eigen::Vector3d::UnitY();
  const Eigen::Vector3d x = helper.cross(z).normalized();
  const Eigen::Vector3d y = z.cross(x);
  Eigen::Matrix4d m = Eigen::Matrix4d::Identity();
  m.block<3, 1>(0, 0) = x;
  m.block<3, 1>(0, 1) = y;
  m.block<3, 1>(0, 2) = z;
  m.block<3, 1>(0, 3) = from;
  return m;
}

Eigen::Matrix4d placement(const Eigen::Vector3d& translate, const Eigen::Vector3d& rotate_deg,
                          const Eigen::Vector3d& scale) {
  const double k = M_PI / 180.0;
  Eigen::Affine3d t = Eigen::Affine3d::Identity();
  t.translate(translate);
  t.rotate(Eigen::AngleAxisd(rotate_deg.z() * k, Eigen::Vector3d::UnitZ()));
  t.rotate(Eigen::AngleAxisd(rotate_deg.y() * k, Eigen::Vector3d::UnitY()));
  t.rotate(Eigen::AngleAxisd(rotate_deg.x() * k, Eigen::Vector3d::UnitX()));
  t.scale(scale);
  return t.matrix();
}

Primitive makeSphere(const Eigen::Vector3d& center, double radius) {
  return makeEllipsoid(center, Eigen::Vector3d::Constant(radius));
}

Primitive makeEllipsoid(const Eigen::Vector3d& center, const Eigen::Vector3d& r) {
  Primitive p = diagonal(1 / (r.x() * r.x()), 1 / (r.y() * r.y()), 1 / (r.z() * r.z()), -1);
  Eigen::Matrix4d t = Eigen::Matrix4d::Identity();
  t.block<3, 1>(0, 3) = center;
  return p.transformed(t);
}

Primitive makeCylinder(const Eigen::Vector3d& base, const Eigen::Vector3d& top, double radius) {
  const double h = (top - base).norm();
  Primitive p = diagonal(1, 1, 0, -radius * radius);
  p.clip = {zAbove(0), zBelow(h)};
  return p.transformed(alignZ(base, top - base));
}

Primitive makeCone(const Eigen::Vector3d& apex, const Eigen::Vector3d& base, double radius) {
  const double h = (base - apex).norm();
  const double k = radius / h;
  Primitive p = diagonal(1, 1, -k * k, 0);
  p.clip = {zAbove(0), zBelow(h)};
  return p.transformed(alignZ(apex, base - apex));
}

Primitive makeParaboloid(double rx, double ry, double height) {
  Primitive p;
  p.quadric = Quadric::fromCoefficients(1 / (rx * rx), 1 / (ry * ry), 0, 0, 0, 0, 0, 0,
                                        -0.5 / height, 0);
  p.clip = {zBelow(height)};
  return p;
}

Primitive makeHyperboloid1(const Eigen::Vector3d& r, double height) {
  Primitive p = diagonal(1 / (r.x() * r.x()), 1 / (r.y() * r.y()), -1 / (r.z() * r.z()), -1);
  p.clip = {zAbove(-height / 2), zBelow(height / 2)};
  return p;
}

Primitive makeHyperboloid2(const Eigen::Vector3d& r, double height) {
  Primitive p = diagonal(1 / (r.x() * r.x()), 1 / (r.y() * r.y()), -1 / (r.z() * r.z()), 1);
  p.clip = {zAbove(-height / 2), zBelow(height / 2)};
  return p;
}

Primitive makeHyperbolicParaboloid(double a, double b, double extent) {
  Primitive p;
  p.quadric = Quadric::fromCoefficients(1 / (a * a), -1 / (b * b), 0, 0, 0, 0, 0, 0, -0.5, 0);
  p.clip = {axisSlab(0, 1, extent), axisSlab(0, -1, extent), axisSlab(1, 1, extent),
            axisSlab(1, -1, extent)};
  return p;
}

Primitive makeEllipticCylinder(double a, double b, double height) {
  Primitive p = diagonal(1 / (a * a), 1 / (b * b), 0, -1);
  p.clip = {zAbove(-height / 2), zBelow(height / 2)};
  return p;
}

Primitive makeHyperbolicCylinder(double a, double b, double extent, double height) {
  // Interior (f <= 0) is the side of each branch that holds its focus:
  // x²/a² - y²/b² >= 1, so f = -x²/a² + y²/b² + 1.
  Primitive p = diagonal(-1 / (a * a), 1 / (b * b), 0, 1);
  p.clip = {axisSlab(0, 1, extent), axisSlab(0, -1, extent), axisSlab(1, 1, extent),
            axisSlab(1, -1, extent), zAbove(-height / 2), zBelow(height / 2)};
  return p;
}

Primitive makeParabolicCylinder(double pp, double extent, double height) {
  Primitive p;
  p.quadric = Quadric::fromCoefficients(1, 0, 0, 0, 0, 0, 0, -pp, 0, 0);  // x² - 2p y
  p.clip = {axisSlab(1, 1, extent), zAbove(-height / 2), zBelow(height / 2)};
  return p;
}

Primitive makePlane(const Eigen::Vector3d& point, const Eigen::Vector3d& normal) {
  const Eigen::Vector3d n = normal.normalized();
  Primitive p;
  p.quadric = Quadric::fromCoefficients(0, 0, 0, 0, 0, 0, n.x() / 2, n.y() / 2, n.z() / 2,
                                        -n.dot(point));
  return p;
}

Primitive makeTriangle(const Eigen::Vector3d& a, const Eigen::Vector3d& b, const Eigen::Vector3d& c) {
  const Eigen::Vector3d n = (b - a).cross(c - a);
  Primitive p = makePlane(a, n);
  // Edge half-spaces: keep the side of each edge that holds the opposite vertex.
  const Eigen::Vector3d verts[3] = {a, b, c};
  for (int e = 0; e < 3; ++e) {
    const Eigen::Vector3d& u = verts[e];
    const Eigen::Vector3d& v = verts[(e + 1) % 3];
    const Eigen::Vector3d out = (v - u).cross(n);  // points away from the triangle (CCW)
    p.clip.push_back(HalfSpace::fromPointNormal(u, out));
  }
  return p;
}

}  // namespace qacc
