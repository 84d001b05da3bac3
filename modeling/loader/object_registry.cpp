#include "modeling/loader/object_registry.h"

#include <cstdio>
#include <cstdlib>
#include <map>

namespace qacc {
namespace {

// The table of scene object types, filled by the modelers' static initialisers (a
// function-local static, so it exists before the first registration whatever the order
// in which object files are initialised).
std::map<std::string, ObjectBuilder>& registry() {
  static std::map<std::string, ObjectBuilder> table;
  return table;
}

}  // namespace

std::string ObjectContext::resolve(const std::string& path) const {
  if (path.empty() || path[0] == '/' || directory.empty()) return path;
  return directory + "/" + path;
}

bool registerObjectTypes(std::initializer_list<std::pair<const char*, ObjectBuilder>> builders) {
  for (const auto& b : builders)
    if (!registry().emplace(b.first, b.second).second) {
      std::fprintf(stderr, "qacc: object type \"%s\" registered twice\n", b.first);
      std::abort();
    }
  return true;
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
