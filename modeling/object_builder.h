// Registry of scene object types (design §6). Each modeler registers a builder for its
// "type" in object_builder.cpp (one line each); the loader calls it with the object's
// JsonNode. The builder reads only its own keys (the loader reads "type", "material",
// "transform", "clip", "solid" and "name" itself and applies them after the builder),
// returns the primitives in the object's local frame, and may add materials or read
// files (relative paths resolve against the scene file's directory).
#pragma once
#include <functional>
#include <string>
#include <vector>

#include "modeling/json_node.h"
#include "modeling/primitive.h"
#include "modeling/scene.h"

namespace qacc {

struct ObjectContext {
  Scene& scene;               // materials may be appended (e.g. per-element colours)
  std::string directory;      // directory of the scene file, for relative paths
  int material;               // the object's material index (from "material" or default)
  bool solid;                 // the object's "solid" flag
  bool has_material = false;  // true when the object named its "material" explicitly
  std::string note;           // the builder's one-line account of what it built (qacc info)
  std::string resolve(const std::string& path) const;  // relative → directory/path
};

using ObjectBuilder = std::function<std::vector<Primitive>(const JsonNode& object, ObjectContext& ctx)>;

// The builder for a type, or nullptr.
const ObjectBuilder* findObjectBuilder(const std::string& type);
// All registered type names (sorted), for messages and documentation.
std::vector<std::string> objectTypes();

}  // namespace qacc
