// JsonNode: strict, path-aware read access to a scene's JSON (design §6 "bad input").
// Every accessor checks type, arity and finiteness and throws SceneError naming the file,
// the JSON Pointer path (e.g. /objects/3/center) and the problem. Keys read through a node
// are recorded; finish() refuses any key of the object that nobody read (unknown keys).
// Loading is linear in the input and cheap per value: a node's path is built once per node
// (children of arrays of numbers get one only to report an error), and only object nodes
// keep a record of the keys read, by the address of the key in the document.
#pragma once
#include <memory>
#include <optional>
#include <string>
#include <vector>

#include <Eigen/Dense>
#include <nlohmann/json.hpp>

#include "modeling/scene/scene_error.h"

namespace qacc {

class JsonNode {
 public:
  JsonNode(const nlohmann::json& j, std::string path, std::shared_ptr<const std::string> file);

  const nlohmann::json& json() const { return *j_; }
  const std::string& path() const { return path_; }
  const std::string& file() const { return *file_; }
  [[noreturn]] void fail(const std::string& problem) const;

  // Objects.
  bool isObject() const { return j_->is_object(); }
  bool has(const std::string& key) const;
  JsonNode at(const std::string& key) const;                  // required key
  std::optional<JsonNode> get(const std::string& key) const;  // optional key
  void finish() const;  // every key of this object must have been read

  // Arrays.
  bool isArray() const { return j_->is_array(); }
  std::size_t size() const;  // array length (fails if not an array)
  JsonNode operator[](std::size_t i) const;
  std::vector<JsonNode> elements() const;

  // Scalars.
  double number() const;                    // finite number
  double positive() const;                  // finite and > 0
  double nonNegative() const;               // finite and >= 0
  long long integer(long long lo, long long hi) const;
  bool boolean() const;
  std::string string() const;
  Eigen::Vector3d vec3() const;
  Eigen::Vector4d vec4() const;
  Eigen::Vector3d color() const;            // 3 numbers in [0, 1]
  Eigen::Matrix4d mat4() const;             // 4 rows of 4 numbers
  std::vector<double> numbers(std::size_t n) const;  // exactly n finite numbers

  // Optional-key shorthands.
  double number(const std::string& key, double def) const;
  double positive(const std::string& key, double def) const;
  bool boolean(const std::string& key, bool def) const;
  std::string string(const std::string& key, const std::string& def) const;
  Eigen::Vector3d vec3(const std::string& key, const Eigen::Vector3d& def) const;

 private:
  const nlohmann::json* j_;
  std::string path_;
  std::shared_ptr<const std::string> file_;
  // Object nodes only: the keys read (their addresses in j_), shared by the node's copies.
  std::shared_ptr<std::vector<const std::string*>> used_;
  const char* typeName() const;
  const nlohmann::json* member(const std::string& key) const;  // nullptr when absent
  std::string childPath(const std::string& key) const;
  void readNumbers(double* out, std::size_t n) const;
};

// JSON Pointer escaping of one key (~ → ~0, / → ~1).
std::string jsonPointerKey(const std::string& key);

}  // namespace qacc
