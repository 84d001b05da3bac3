#include "modeling/scene/strict_json.h"

#include <vector>

#include "modeling/scene/json_location.h"
#include "modeling/scene/json_node.h"
#include "modeling/scene/plain_json.h"
#include "modeling/scene/scene_error.h"

namespace qacc {

namespace {

using nlohmann::json;

// Builds the DOM and keeps, for every open object or array, where the next value goes and
// its JSON path element.
class StrictBuilder {
 public:
  StrictBuilder(const std::string& text, const std::string& file) : text_(text), file_(file) {}
  json result;

  bool null() { return put(json(nullptr)); }
  bool boolean(bool v) { return put(json(v)); }
  bool number_integer(json::number_integer_t v) { return put(json(v)); }
  bool number_unsigned(json::number_unsigned_t v) { return put(json(v)); }
  bool number_float(json::number_float_t v, const json::string_t&) { return put(json(v)); }
  bool string(json::string_t& v) { return put(json(std::move(v))); }
  bool binary(json::binary_t& v) { return put(json(std::move(v))); }

  bool start_object(std::size_t) {
    open(json::object(), false);
    return true;
  }
  bool key(json::string_t& k) {
    Open& o = stack_.back();
    // One look-up: the key is moved in when new and left as it is when already there.
    const auto [it, inserted] = o.node->get_ref<json::object_t&>().try_emplace(std::move(k));
    if (!inserted)
      throw SceneError(file_, path(stack_.size()) + "/" + jsonPointerKey(k), "duplicate key '" + k + "'");
    o.key = &it->first;
    o.slot = &it->second;
    return true;
  }
  bool end_object() { return close(); }
  bool start_array(std::size_t) {
    // Most arrays of a scene are points, colours or planes: room for four values at once
    // instead of three reallocations.
    json a = json::array();
    a.get_ref<json::array_t&>().reserve(4);
    open(std::move(a), true);
    return true;
  }
  bool end_array() { return close(); }

  bool parse_error(std::size_t position, const std::string&, const nlohmann::detail::exception& ex) {
    std::string detail = ex.what();
    if (ex.id == 406) {
      // A number that overflows a double (e.g. 1e999): the value being read is the next one
      // of the innermost open object or array.
      const auto pos = detail.find("] ");
      if (pos != std::string::npos) detail = detail.substr(pos + 2);
      throw SceneError(file_, nextPath(), "number is not finite (" + detail + ")");
    }
    // nlohmann's position counts the byte it stopped on from 1.
    const TextPosition at = textPosition(text_, position > 0 ? position - 1 : 0);
    const auto pos = detail.find("syntax error");
    if (pos != std::string::npos) detail = detail.substr(pos);
    throw SceneError(file_, "/", "JSON syntax error at line " + std::to_string(at.line) + ", column " +
                                    std::to_string(at.column) + ": " + detail);
  }

 private:
  struct Open {
    json* node;
    bool array;
    const std::string* key = nullptr;  // objects: the current key (in the document)
    json* slot = nullptr;  // objects: where the current key's value goes
  };
  const std::string& text_;
  const std::string& file_;
  std::vector<Open> stack_;

  json* place(json&& v) {
    if (stack_.empty()) {
      result = std::move(v);
      return &result;
    }
    Open& o = stack_.back();
    if (o.array) {
      o.node->push_back(std::move(v));
      return &o.node->back();
    }
    *o.slot = std::move(v);
    return o.slot;
  }
  bool put(json&& v) {
    place(std::move(v));
    return true;
  }
  void open(json&& v, bool array) {
    json* node = place(std::move(v));
    stack_.push_back(Open{node, array, nullptr, nullptr});
  }
  bool close() {
    stack_.pop_back();
    return true;
  }
  std::string element(const Open& o, bool next) const {
    if (o.array) return std::to_string(o.node->size() - (next ? 0 : 1));
    return o.key ? jsonPointerKey(*o.key) : std::string();
  }
  // Path of the innermost open container's elements up to depth `upto` (the current ones).
  std::string path(std::size_t upto) const {
    std::string p;
    for (std::size_t i = 0; i + 1 < upto; ++i) p += "/" + element(stack_[i], false);
    return p;
  }
  std::string nextPath() const {
    if (stack_.empty()) return "/";
    return path(stack_.size()) + "/" + element(stack_.back(), true);
  }
};

}  // namespace

json parseStrictJson(const std::string& text, const std::string& file) {
  if (auto plain = parsePlainJson(text)) return std::move(*plain);
  StrictBuilder b(text, file);
  json::sax_parse(text, &b, json::input_format_t::json, /*strict=*/true, /*ignore_comments=*/false);
  return std::move(b.result);
}

}  // namespace qacc
