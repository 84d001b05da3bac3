#include "modeling/modelers/natural_objects.h"

#include <cmath>

#include "modeling/geometry/natural_quadrics.h"

namespace qacc {
namespace {

Eigen::Vector3d positiveVec3(const JsonNode& n) {
  const Eigen::Vector3d v = n.vec3();
  for (int i = 0; i < 3; ++i)
    if (!(v[i] > 0)) n[std::size_t(i)].fail("expected a positive number");
  return v;
}

// Two points given as two keys must differ (the axis of a cylinder or cone).
void distinct(const JsonNode& o, const char* key, const Eigen::Vector3d& a, const Eigen::Vector3d& b) {
  if (!((a - b).norm() > 0)) o.at(key).fail(std::string(key) + " must differ from the other end point");
}

}  // namespace

std::vector<Primitive> buildSphere(const JsonNode& o, ObjectContext&) {
  const Eigen::Vector3d c = o.vec3("center", Eigen::Vector3d::Zero());
  const double r = o.at("radius").positive();
  return {makeSphere(c, r)};
}

std::vector<Primitive> buildEllipsoid(const JsonNode& o, ObjectContext&) {
  const Eigen::Vector3d c = o.vec3("center", Eigen::Vector3d::Zero());
  const Eigen::Vector3d r = positiveVec3(o.at("radii"));
  return {makeEllipsoid(c, r)};
}

std::vector<Primitive> buildCylinder(const JsonNode& o, ObjectContext&) {
  const Eigen::Vector3d base = o.vec3("base", Eigen::Vector3d::Zero());
  const Eigen::Vector3d top = o.vec3("top", Eigen::Vector3d::UnitZ());
  distinct(o, o.has("top") ? "top" : "base", base, top);
  const double r = o.at("radius").positive();
  return {makeCylinder(base, top, r)};
}

std::vector<Primitive> buildCone(const JsonNode& o, ObjectContext&) {
  const Eigen::Vector3d apex = o.vec3("apex", Eigen::Vector3d::Zero());
  const Eigen::Vector3d base = o.vec3("base", Eigen::Vector3d::UnitZ());
  distinct(o, o.has("base") ? "base" : "apex", apex, base);
  const double r = o.at("radius").positive();
  return {makeCone(apex, base, r)};
}

std::vector<Primitive> buildParaboloid(const JsonNode& o, ObjectContext&) {
  double rx, ry;
  auto radius = o.get("radius");
  auto radii = o.get("radii");
  if (radius && radii) radii->fail("give either 'radius' or 'radii', not both");
  if (radius) {
    rx = ry = radius->positive();
  } else if (radii) {
    const auto v = radii->numbers(2);
    for (std::size_t i = 0; i < 2; ++i)
      if (!(v[i] > 0)) (*radii)[i].fail("expected a positive number");
    rx = v[0];
    ry = v[1];
  } else {
    o.fail("missing required key 'radius' (or 'radii': [rx, ry])");
  }
  const double h = o.at("height").positive();
  return {makeParaboloid(rx, ry, h)};
}

std::vector<Primitive> buildHyperboloid1(const JsonNode& o, ObjectContext&) {
  const Eigen::Vector3d r = positiveVec3(o.at("radii"));
  return {makeHyperboloid1(r, o.at("height").positive())};
}

std::vector<Primitive> buildHyperboloid2(const JsonNode& o, ObjectContext&) {
  const Eigen::Vector3d r = positiveVec3(o.at("radii"));
  const JsonNode hn = o.at("height");
  const double h = hn.positive();
  if (!(h / 2 > r.z())) hn.fail("height must exceed 2 c (the sheets start at z = ±c), got " + hn.json().dump());
  return {makeHyperboloid2(r, h)};
}

std::vector<Primitive> buildHyperbolicParaboloid(const JsonNode& o, ObjectContext&) {
  const double a = o.at("a").positive();
  const double b = o.at("b").positive();
  return {makeHyperbolicParaboloid(a, b, o.at("extent").positive())};
}

std::vector<Primitive> buildEllipticCylinder(const JsonNode& o, ObjectContext&) {
  const double a = o.at("a").positive();
  const double b = o.at("b").positive();
  return {makeEllipticCylinder(a, b, o.at("height").positive())};
}

std::vector<Primitive> buildHyperbolicCylinder(const JsonNode& o, ObjectContext&) {
  const double a = o.at("a").positive();
  const double b = o.at("b").positive();
  const JsonNode en = o.at("extent");
  const double extent = en.positive();
  if (!(extent > a)) en.fail("extent must exceed a (the branches start at |x| = a)");
  return {makeHyperbolicCylinder(a, b, extent, o.at("height").positive())};
}

std::vector<Primitive> buildParabolicCylinder(const JsonNode& o, ObjectContext&) {
  const double p = o.at("p").positive();
  const double extent = o.at("extent").positive();
  return {makeParabolicCylinder(p, extent, o.at("height").positive())};
}

std::vector<Primitive> buildPlane(const JsonNode& o, ObjectContext&) {
  const Eigen::Vector3d point = o.vec3("point", Eigen::Vector3d::Zero());
  const JsonNode nn = o.at("normal");
  const Eigen::Vector3d n = nn.vec3();
  if (!(n.norm() > 0)) nn.fail("normal must be a non-zero vector");
  return {makePlane(point, n)};
}

std::vector<Primitive> buildQuadric(const JsonNode& o, ObjectContext&) {
  const JsonNode mn = o.at("matrix");
  const Eigen::Matrix4d m = mn.mat4();
  const double scale = m.cwiseAbs().maxCoeff();
  if (!(scale > 0)) mn.fail("matrix is all zero");
  for (int r = 0; r < 4; ++r)
    for (int c = r + 1; c < 4; ++c)
      if (std::abs(m(r, c) - m(c, r)) > kQuadricSymmetryTolerance * scale)
        mn[std::size_t(r)][std::size_t(c)].fail("matrix is not symmetric: element [" + std::to_string(r) + "][" +
                                                std::to_string(c) + "] differs from [" + std::to_string(c) +
                                                "][" + std::to_string(r) + "]");
  Primitive p;
  p.quadric = Quadric(m);
  return {p};
}

std::vector<Primitive> buildTriangle(const JsonNode& o, ObjectContext& ctx) {
  if (ctx.solid) o.at("solid").fail("a triangle is a facet; solid display is meaningless");
  const JsonNode vn = o.at("vertices");
  if (vn.size() != 3) vn.fail("expected 3 vertices, got " + std::to_string(vn.size()));
  const Eigen::Vector3d a = vn[0].vec3(), b = vn[1].vec3(), c = vn[2].vec3();
  const double scale = std::max({(b - a).norm(), (c - a).norm(), (c - b).norm()});
  if (!((b - a).cross(c - a).norm() > 1e-12 * scale * scale)) vn.fail("triangle is degenerate (zero area)");
  return {makeTriangle(a, b, c)};
}

namespace {
// The scene object types this modeler provides (loader/object_registry.h).
[[maybe_unused]] const bool kRegistered = registerObjectTypes({
    {"cone", buildCone},
    {"cylinder", buildCylinder},
    {"ellipsoid", buildEllipsoid},
    {"elliptic_cylinder", buildEllipticCylinder},
    {"hyperbolic_cylinder", buildHyperbolicCylinder},
    {"hyperbolic_paraboloid", buildHyperbolicParaboloid},
    {"hyperboloid1", buildHyperboloid1},
    {"hyperboloid2", buildHyperboloid2},
    {"parabolic_cylinder", buildParabolicCylinder},
    {"paraboloid", buildParaboloid},
    {"plane", buildPlane},
    {"quadric", buildQuadric},
    {"sphere", buildSphere},
    {"triangle", buildTriangle},
});

}  // namespace

}  // namespace qacc
