#include "modeling/scene/json_node.h"

#include <algorithm>
#include <cmath>

namespace qacc {

std::string jsonPointerKey(const std::string& key) {
  std::string out;
  for (char c : key) {
    if (c == '~') out += "~0";
    else if (c == '/') out += "~1";
    else out += c;
  }
  return out;
}

JsonNode::JsonNode(const nlohmann::json& j, std::string path, std::shared_ptr<const std::string> file)
    : j_(&j), path_(std::move(path)), file_(std::move(file)) {
  if (j.is_object()) used_ = std::make_shared<std::vector<const std::string*>>();
}

void JsonNode::fail(const std::string& problem) const { throw SceneError(*file_, path_, problem); }

const char* JsonNode::typeName() const {
  switch (j_->type()) {
    case nlohmann::json::value_t::null: return "null";
    case nlohmann::json::value_t::object: return "an object";
    case nlohmann::json::value_t::array: return "an array";
    case nlohmann::json::value_t::string: return "a string";
    case nlohmann::json::value_t::boolean: return "a boolean";
    case nlohmann::json::value_t::number_integer:
    case nlohmann::json::value_t::number_unsigned:
    case nlohmann::json::value_t::number_float: return "a number";
    default: return "an unsupported value";
  }
}

bool JsonNode::has(const std::string& key) const {
  if (!j_->is_object()) fail(std::string("expected an object, got ") + typeName());
  return j_->contains(key);
}

const nlohmann::json* JsonNode::member(const std::string& key) const {
  if (!j_->is_object()) fail(std::string("expected an object, got ") + typeName());
  const auto& object = j_->get_ref<const nlohmann::json::object_t&>();
  const auto it = object.find(key);
  if (it == object.end()) return nullptr;
  used_->push_back(&it->first);
  return &it->second;
}

std::string JsonNode::childPath(const std::string& key) const {
  std::string p;
  p.reserve(path_.size() + 1 + key.size());
  p += path_;
  p += '/';
  if (key.find_first_of("~/") == std::string::npos) p += key;
  else p += jsonPointerKey(key);
  return p;
}

JsonNode JsonNode::at(const std::string& key) const {
  const nlohmann::json* v = member(key);
  if (!v) fail("missing required key '" + key + "'");
  return JsonNode(*v, childPath(key), file_);
}

std::optional<JsonNode> JsonNode::get(const std::string& key) const {
  const nlohmann::json* v = member(key);
  if (!v) return std::nullopt;
  return JsonNode(*v, childPath(key), file_);
}

void JsonNode::finish() const {
  if (!j_->is_object()) return;
  std::vector<const std::string*>& used = *used_;
  std::sort(used.begin(), used.end());
  const auto& object = j_->get_ref<const nlohmann::json::object_t&>();
  for (const auto& [key, value] : object)
    if (!std::binary_search(used.begin(), used.end(), &key))
      JsonNode(value, childPath(key), file_).fail("unknown key '" + key + "'");
}

std::size_t JsonNode::size() const {
  if (!j_->is_array()) fail(std::string("expected an array, got ") + typeName());
  return j_->size();
}

JsonNode JsonNode::operator[](std::size_t i) const {
  if (i >= size()) fail("index " + std::to_string(i) + " out of range");
  return JsonNode((*j_)[i], path_ + "/" + std::to_string(i), file_);
}

std::vector<JsonNode> JsonNode::elements() const {
  std::vector<JsonNode> out;
  const std::size_t n = size();
  out.reserve(n);
  for (std::size_t i = 0; i < n; ++i) out.push_back((*this)[i]);
  return out;
}

double JsonNode::number() const {
  if (!j_->is_number()) fail(std::string("expected a number, got ") + typeName());
  const double v = j_->get<double>();
  if (!std::isfinite(v)) fail("number is not finite");
  return v;
}

double JsonNode::positive() const {
  const double v = number();
  if (!(v > 0)) fail("expected a positive number, got " + j_->dump());
  return v;
}

double JsonNode::nonNegative() const {
  const double v = number();
  if (!(v >= 0)) fail("expected a non-negative number, got " + j_->dump());
  return v;
}

long long JsonNode::integer(long long lo, long long hi) const {
  const double v = number();
  if (std::floor(v) != v) fail("expected an integer, got " + j_->dump());
  if (v < double(lo) || v > double(hi))
    fail("expected an integer in [" + std::to_string(lo) + ", " + std::to_string(hi) + "], got " + j_->dump());
  return static_cast<long long>(v);
}

bool JsonNode::boolean() const {
  if (!j_->is_boolean()) fail(std::string("expected true or false, got ") + typeName());
  return j_->get<bool>();
}

std::string JsonNode::string() const {
  if (!j_->is_string()) fail(std::string("expected a string, got ") + typeName());
  return j_->get<std::string>();
}

void JsonNode::readNumbers(double* out, std::size_t n) const {
  if (!j_->is_array()) fail("expected an array of " + std::to_string(n) + " numbers, got " + typeName());
  if (j_->size() != n)
    fail("expected " + std::to_string(n) + " numbers, got " + std::to_string(j_->size()));
  for (std::size_t i = 0; i < n; ++i) {
    const nlohmann::json& e = (*j_)[i];
    if (e.is_number()) {
      const double v = e.get<double>();
      if (std::isfinite(v)) {
        out[i] = v;
        continue;
      }
    }
    out[i] = (*this)[i].number();  // refuses it, with the element's path
  }
}

std::vector<double> JsonNode::numbers(std::size_t n) const {
  std::vector<double> out(n);
  readNumbers(out.data(), n);
  return out;
}

Eigen::Vector3d JsonNode::vec3() const {
  Eigen::Vector3d v;
  readNumbers(v.data(), 3);
  return v;
}

Eigen::Vector4d JsonNode::vec4() const {
  Eigen::Vector4d v;
  readNumbers(v.data(), 4);
  return v;
}

Eigen::Vector3d JsonNode::color() const {
  const Eigen::Vector3d c = vec3();
  for (int i = 0; i < 3; ++i)
    if (c[i] < 0 || c[i] > 1) (*this)[i].fail("colour component must be in [0, 1]");
  return c;
}

Eigen::Matrix4d JsonNode::mat4() const {
  if (!j_->is_array() || j_->size() != 4) fail("expected 4 rows of 4 numbers");
  Eigen::Matrix4d m;
  for (std::size_t r = 0; r < 4; ++r) m.row(Eigen::Index(r)) = (*this)[r].vec4().transpose();
  return m;
}

double JsonNode::number(const std::string& key, double def) const {
  auto n = get(key);
  return n ? n->number() : def;
}
double JsonNode::positive(const std::string& key, double def) const {
  auto n = get(key);
  return n ? n->positive() : def;
}
bool JsonNode::boolean(const std::string& key, bool def) const {
  auto n = get(key);
  return n ? n->boolean() : def;
}
std::string JsonNode::string(const std::string& key, const std::string& def) const {
  auto n = get(key);
  return n ? n->string() : def;
}
Eigen::Vector3d JsonNode::vec3(const std::string& key, const Eigen::Vector3d& def) const {
  auto n = get(key);
  return n ? n->vec3() : def;
}

}  // namespace qacc
