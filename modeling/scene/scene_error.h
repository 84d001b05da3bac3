// SceneError: bad scene input, with the message "FILE: JSON-PATH: PROBLEM".
#pragma once
#include <stdexcept>
#include <string>

namespace qacc {

class SceneError : public std::runtime_error {
 public:
  SceneError(const std::string& file, const std::string& path, const std::string& problem)
      : std::runtime_error(file + ": " + (path.empty() ? "/" : path) + ": " + problem),
        file_(file), path_(path.empty() ? "/" : path), problem_(problem) {}
  const std::string& file() const { return file_; }
  const std::string& jsonPath() const { return path_; }
  const std::string& problem() const { return problem_; }

 private:
  std::string file_, path_, problem_;
};

}  // namespace qacc
