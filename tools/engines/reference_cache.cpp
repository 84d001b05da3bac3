#include "tools/engines/reference_cache.h"

#include <cstdint>
#include <cstdio>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <sstream>
#include <stdexcept>

#include <unistd.h>

#include <nlohmann/json.hpp>

#include "raster/image/png_io.h"
#include "raster/reference/reference_renderer.h"

namespace qacc {

namespace fs = std::filesystem;

namespace {

// Two independent 64-bit FNV-1a streams: a 128-bit content hash.
struct Hash128 {
  std::uint64_t a = 1469598103934665603ULL, b = 0x9e3779b97f4a7c15ULL;
  void add(const void* p, std::size_t n) {
    const auto* c = static_cast<const unsigned char*>(p);
    for (std::size_t i = 0; i < n; ++i) {
      a = (a ^ c[i]) * 1099511628211ULL;
      b = (b ^ c[i]) * 0x100000001b3ULL + 0x5bd1e995ULL;
    }
  }
  void add(const std::string& s) {
    const std::uint64_t n = s.size();
    add(&n, sizeof n);
    add(s.data(), s.size());
  }
  std::string hex() const {
    char buf[40];
    std::snprintf(buf, sizeof buf, "%016llx%016llx", (unsigned long long)a, (unsigned long long)b);
    return buf;
  }
};

std::string readBytes(const fs::path& p) {
  std::ifstream in(p, std::ios::binary);
  std::ostringstream ss;
  ss << in.rdbuf();
  return ss.str();
}

// Every string of the scene that names an existing file (PDB, OBJ...), in document order.
void hashNamedFiles(const nlohmann::json& j, const std::string& dir, Hash128& h) {
  if (j.is_string()) {
    const std::string s = j.get<std::string>();
    if (s.empty() || s.size() > 4096) return;
    const fs::path p = fs::path(s).is_absolute() ? fs::path(s) : fs::path(dir) / s;
    std::error_code ec;
    if (fs::is_regular_file(p, ec)) {
      h.add(s);
      h.add(readBytes(p));
    }
  } else if (j.is_structured()) {
    for (const auto& v : j) hashNamedFiles(v, dir, h);
  }
}

}  // namespace

ReferenceCache::ReferenceCache(const std::string& dir) : dir_(dir) {
  if (dir_.empty()) {
    const char* env = std::getenv("QACC_CACHE");
    const char* home = std::getenv("HOME");
    dir_ = env && *env ? env : (std::string(home && *home ? home : ".") + "/.cache/qacc");
  }
}

std::string ReferenceCache::key(const std::string& sceneText, const std::string& sceneDir, int width, int height) {
  Hash128 h;
  h.add(std::string(kReferenceRendererVersion));
  h.add(sceneText);
  const std::int32_t size[2] = {width, height};
  h.add(size, sizeof size);
  const nlohmann::json doc = nlohmann::json::parse(sceneText, nullptr, false);
  if (!doc.is_discarded()) hashNamedFiles(doc, sceneDir, h);
  return h.hex();
}

FrameBuffer ReferenceCache::get(const std::string& sceneText, const std::string& sceneDir, int width, int height,
                                const std::function<Scene()>& scene, int threads, bool primitiveIds) {
  const std::string k = key(sceneText, sceneDir, width, height);
  const fs::path frame = fs::path(dir_) / (k + ".frame");
  FrameBuffer fb;
  if (disabled_) {
    Scene s = scene();
    s.width = width;
    s.height = height;
    ++renders_;
    fb = renderReference(s, threads);
    if (!primitiveIds) fb.primitive = {};
    return fb;
  }
  if (readFrameBuffer(frame.string(), fb, primitiveIds) && fb.width == width && fb.height == height) {
    ++hits_;
    return fb;
  }
  Scene s = scene();
  s.width = width;
  s.height = height;
  fb = renderReference(s, threads);
  ++renders_;
  std::error_code ec;
  fs::create_directories(dir_, ec);
  if (ec) throw std::invalid_argument(dir_ + ": cannot create the reference cache directory: " + ec.message());
  const std::string tmp = frame.string() + ".tmp" + std::to_string(::getpid());
  writeFrameBuffer(tmp, fb);
  writePng((fs::path(dir_) / (k + ".png")).string(), fb.color);
  fs::rename(tmp, frame, ec);
  if (ec) throw std::invalid_argument(frame.string() + ": cannot store the reference frame: " + ec.message());
  if (!primitiveIds) fb.primitive = {};
  return fb;
}

namespace {
constexpr char kMagic[8] = {'Q', 'A', 'C', 'C', 'F', 'B', '1', '\n'};
}

void writeFrameBuffer(const std::string& path, const FrameBuffer& fb) {
  std::ofstream out(path, std::ios::binary);
  if (!out) throw std::invalid_argument(path + ": cannot write");
  out.write(kMagic, sizeof kMagic);
  const std::int32_t size[2] = {fb.width, fb.height};
  out.write(reinterpret_cast<const char*>(size), sizeof size);
  out.write(reinterpret_cast<const char*>(fb.color.data.data()), std::streamsize(fb.color.data.size()));
  out.write(reinterpret_cast<const char*>(fb.depth.data()), std::streamsize(fb.depth.size() * sizeof(double)));
  out.write(reinterpret_cast<const char*>(fb.object.data()), std::streamsize(fb.object.size() * sizeof(std::int32_t)));
  out.write(reinterpret_cast<const char*>(fb.primitive.data()),
            std::streamsize(fb.primitive.size() * sizeof(std::int32_t)));
  if (!out) throw std::invalid_argument(path + ": cannot write");
}

bool readFrameBuffer(const std::string& path, FrameBuffer& fb, bool primitiveIds) {
  std::ifstream in(path, std::ios::binary);
  if (!in) return false;
  char magic[8];
  std::int32_t size[2];
  if (!in.read(magic, sizeof magic) || std::string(magic, 8) != std::string(kMagic, 8)) return false;
  if (!in.read(reinterpret_cast<char*>(size), sizeof size) || size[0] <= 0 || size[1] <= 0 ||
      (long long)size[0] * size[1] > (1LL << 28))
    return false;
  const std::size_t n = std::size_t(size[0]) * std::size_t(size[1]);
  // Colour, depth, object and primitive ids: the file must be exactly that long.
  const std::streamoff header = std::streamoff(sizeof kMagic + sizeof size);
  const std::streamoff body = std::streamoff(n * (3 + sizeof(double) + 2 * sizeof(std::int32_t)));
  in.seekg(0, std::ios::end);
  if (!in || in.tellg() != header + body) return false;
  in.seekg(header);
  // Every pixel is read, so nothing is cleared first.
  FrameBuffer f;
  f.width = size[0];
  f.height = size[1];
  f.color = Image8::uninitialised(size[0], size[1], 3);
  f.depth.resize(n);
  f.object.resize(n);
  if (primitiveIds) f.primitive.resize(n);
  in.read(reinterpret_cast<char*>(f.color.data.data()), std::streamsize(f.color.data.size()));
  in.read(reinterpret_cast<char*>(f.depth.data()), std::streamsize(n * sizeof(double)));
  in.read(reinterpret_cast<char*>(f.object.data()), std::streamsize(n * sizeof(std::int32_t)));
  if (primitiveIds) in.read(reinterpret_cast<char*>(f.primitive.data()), std::streamsize(n * sizeof(std::int32_t)));
  if (!in) return false;
  fb = std::move(f);
  return true;
}

}  // namespace qacc
