// Registry of scene object types (design §6). Each modeler registers the builders of its
// types from its own .cpp (`const bool registered = registerObjectTypes({...})`), so the
// registry includes no modeler and adding a modeler touches no other file; the loader
// calls a builder with the object's JsonNode. The builder reads only its own keys (the loader reads "type", "material",
// "transform", "clip", "solid" and "name" itself and applies them after the builder),
// returns the primitives in the object's local frame, and may add materials or read
// files (relative paths resolve against the scene file's directory).
#pragma once
#include <functional>
#include <initializer_list>
#include <utility>
#include <string>
#include <vector>

#include "modeling/scene/json_node.h"
#include "modeling/geometry/primitive.h"
#include "modeling/scene/scene.h"
#include "modeling/scene/view_volume.h"
#include "modeling/support/limits.h"

namespace qacc {

struct ObjectContext {
  Scene& scene;               // materials may be appended (e.g. per-element colours)
  const std::string& directory;  // directory of the scene file, for relative paths
  int material;               // the object's material index (from "material" or default)
  bool solid;                 // the object's "solid" flag
  bool has_material = false;  // true when the object named its "material" explicitly
  std::string note;           // the builder's one-line account of what it built (qacc info)
  const Limits& limits;       // the work the scene may ask for (support/limits.h)
  std::string resolve(const std::string& path) const;  // relative → directory/path
  // View culling (loader/view_culling.h): the view volume in the object's local frame (the
  // frame the builder returns its primitives in), or null when nothing may be culled. A
  // builder may skip any piece whose conservative bounds miss it.
  const ViewVolume* view = nullptr;
  // The cells of the object's whole model, independent of the view (e.g. the algebraic
  // modeler's Kuhn tetrahedra at its level), for a builder that gives an exact surface: the
  // facets engine sizes the surface's mesh by it (tessellation/exact_facets.h), so that view
  // culling, which lowers the pieces emitted, does not change that mesh. 0: not given.
  std::size_t model_cells = 0;
};

using ObjectBuilder = std::function<std::vector<Primitive>(const JsonNode& object, ObjectContext& ctx)>;

// Adds builders under their type names (from a modeler's static initialiser); a name
// registered twice is a programming error and aborts at start-up. Returns true.
bool registerObjectTypes(std::initializer_list<std::pair<const char*, ObjectBuilder>> builders);
// The builder for a type, or nullptr.
const ObjectBuilder* findObjectBuilder(const std::string& type);
// All registered type names (sorted), for messages and documentation.
std::vector<std::string> objectTypes();

}  // namespace qacc
