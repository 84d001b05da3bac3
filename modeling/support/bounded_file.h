// Reading an input file whole, with a size bound: a directory, a device that never ends
// (/dev/zero) or a file above the bound is refused with the reason instead of being read
// forever or into all memory.
#pragma once
#include <cstddef>
#include <stdexcept>
#include <string>

namespace qacc {

struct FileReadError : std::runtime_error {
  using std::runtime_error::runtime_error;
};

// The file's bytes. Throws FileReadError naming `kind` ("scene file", "PDB file"): "cannot open
// KIND: <reason>", "KIND is a directory", "KIND is larger than N bytes (raise the limit with
// --max-input-mb)", "cannot read KIND: <reason>".
std::string readFileBounded(const std::string& path, std::size_t max_bytes, const std::string& kind);
// The same for a file a modeler reads (PDB, OBJ): std::runtime_error "PATH: <reason>".
std::string readModelFile(const std::string& path, std::size_t max_bytes, const std::string& kind);

}  // namespace qacc
