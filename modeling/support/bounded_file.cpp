#include "modeling/support/bounded_file.h"

#include <sys/stat.h>

#include <cerrno>
#include <cstdio>
#include <cstring>
#include <memory>

namespace qacc {

std::string readFileBounded(const std::string& path, std::size_t max_bytes, const std::string& kind) {
  struct stat st {};
  if (::stat(path.c_str(), &st) == 0 && S_ISDIR(st.st_mode)) throw FileReadError(kind + " is a directory");
  struct Closer {
    void operator()(std::FILE* f) const { std::fclose(f); }
  };
  errno = 0;
  std::unique_ptr<std::FILE, Closer> f(std::fopen(path.c_str(), "rb"));
  if (!f) throw FileReadError("cannot open " + kind + ": " + std::strerror(errno));
  std::string text;
  if (S_ISREG(st.st_mode) && st.st_size > 0) {
    if (std::size_t(st.st_size) > max_bytes)
      throw FileReadError(kind + " is larger than " + std::to_string(max_bytes) + " bytes (" + std::to_string(st.st_size) +
                          "; raise the limit with --max-input-mb)");
    text.reserve(std::size_t(st.st_size));
  }
  // Devices and pipes have no size: read in blocks and stop one byte past the bound.
  char buf[1 << 16];
  for (;;) {
    const std::size_t n = std::fread(buf, 1, sizeof buf, f.get());
    if (n > 0) {
      if (text.size() + n > max_bytes)
        throw FileReadError(kind + " is larger than " + std::to_string(max_bytes) +
                            " bytes (raise the limit with --max-input-mb)");
      text.append(buf, n);
    }
    if (n < sizeof buf) {
      if (std::ferror(f.get())) throw FileReadError("cannot read " + kind + ": " + std::strerror(errno));
      break;
    }
  }
  return text;
}

std::string readModelFile(const std::string& path, std::size_t max_bytes, const std::string& kind) {
  try {
    return readFileBounded(path, max_bytes, kind);
  } catch (const FileReadError& e) {
    throw std::runtime_error(path + ": " + e.what());
  }
}

}  // namespace qacc
