#include "modeling/object_builder.h"

#include <map>

#include "modeling/algebraic_object.h"
#include "modeling/bspline_object.h"
#include "modeling/macropatch.h"
#include "modeling/molecule.h"
#include "modeling/natural_objects.h"
#include "modeling/revolution.h"
#include "modeling/triangle_mesh.h"

namespace qacc {
namespace {

// The table of scene object types: one line per type (design §6). Keep it sorted.
const std::map<std::string, ObjectBuilder>& registry() {
  static const std::map<std::string, ObjectBuilder> table = {
      {"algebraic", buildAlgebraic},
      {"bspline", buildBspline},
      {"cone", buildCone},
      {"cylinder", buildCylinder},
      {"ellipsoid", buildEllipsoid},
      {"elliptic_cylinder", buildEllipticCylinder},
      {"hyperbolic_cylinder", buildHyperbolicCylinder},
      {"hyperbolic_paraboloid", buildHyperbolicParaboloid},
      {"hyperboloid1", buildHyperboloid1},
      {"hyperboloid2", buildHyperboloid2},
      {"macropatch", buildMacropatch},
      {"parabolic_cylinder", buildParabolicCylinder},
      {"paraboloid", buildParaboloid},
      {"pdb", buildPdb},
      {"plane", buildPlane},
      {"quadric", buildQuadric},
      {"revolution", buildRevolution},
      {"sphere", buildSphere},
      {"triangle", buildTriangle},
      {"triangle_mesh", buildTriangleMesh},
  };
  return table;
}

}  // namespace

std::string ObjectContext::resolve(const std::string& path) const {
  if (path.empty() || path[0] == '/' || directory.empty()) return path;
  return directory + "/" + path;
}

const ObjectBuilder* findObjectBuilder(const std::string& type) {
  const auto& t = registry();
  auto it = t.find(type);
  return it == t.end() ? nullptr : &it->second;
}

std::vector<std::string> objectTypes() {
  std::vector<std::string> out;
  for (const auto& kv : registry()) out.push_back(kv.first);
  return out;
}

}  // namespace qacc
