// Scene-object builders (object_builder.h) for the natural and specific quadrics, planes,
// general quadric matrices and single triangles. Each reads only its own keys; the keys
// and their defaults are documented in docs/SCENES.md.
#pragma once
#include <vector>

#include "modeling/loader/object_registry.h"

namespace qacc {

std::vector<Primitive> buildSphere(const JsonNode& o, ObjectContext& ctx);
std::vector<Primitive> buildEllipsoid(const JsonNode& o, ObjectContext& ctx);
std::vector<Primitive> buildCylinder(const JsonNode& o, ObjectContext& ctx);
std::vector<Primitive> buildCone(const JsonNode& o, ObjectContext& ctx);
std::vector<Primitive> buildParaboloid(const JsonNode& o, ObjectContext& ctx);
std::vector<Primitive> buildHyperboloid1(const JsonNode& o, ObjectContext& ctx);
std::vector<Primitive> buildHyperboloid2(const JsonNode& o, ObjectContext& ctx);
std::vector<Primitive> buildHyperbolicParaboloid(const JsonNode& o, ObjectContext& ctx);
std::vector<Primitive> buildEllipticCylinder(const JsonNode& o, ObjectContext& ctx);
std::vector<Primitive> buildHyperbolicCylinder(const JsonNode& o, ObjectContext& ctx);
std::vector<Primitive> buildParabolicCylinder(const JsonNode& o, ObjectContext& ctx);
std::vector<Primitive> buildPlane(const JsonNode& o, ObjectContext& ctx);
std::vector<Primitive> buildQuadric(const JsonNode& o, ObjectContext& ctx);
std::vector<Primitive> buildTriangle(const JsonNode& o, ObjectContext& ctx);

// Relative tolerance of the "quadric" type's symmetry check: |M - Mᵀ| <= 1e-9 max|M|.
constexpr double kQuadricSymmetryTolerance = 1e-9;

}  // namespace qacc
