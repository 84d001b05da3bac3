// Strict JSON text → nlohmann::json for scene and configuration files: syntax errors with
// line and column, duplicate keys refused with their JSON path (nlohmann keeps the last one
// silently; a strict loader must not), numbers that overflow a double refused with the path
// of the value. Plain JSON (plain_json.h: no escapes, no duplicates, finite numbers) is read
// by a fast reader that keeps no positions; anything else, and so every error, by a SAX
// handler in one pass, linear in the size of the text (the DOM callback parser used before
// was quadratic in the number of objects: 1 M spheres took over 200 s).
#pragma once
#include <string>

#include <nlohmann/json.hpp>

namespace qacc {

// Throws SceneError(file, path, problem).
nlohmann::json parseStrictJson(const std::string& text, const std::string& file);

}  // namespace qacc
