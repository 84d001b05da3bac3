#include "modeling/modelers/triangle_mesh.h"

#include <cerrno>
#include <cmath>
#include <cstdlib>
#include <cstring>
#include <fstream>
#include <sstream>
#include <stdexcept>

#include "modeling/geometry/natural_quadrics.h"
#include "modeling/support/bounded_file.h"

namespace qacc {
namespace {

[[noreturn]] void lineError(const std::string& name, std::size_t line, const std::string& problem) {
  throw std::runtime_error(name + ":" + std::to_string(line) + ": " + problem);
}

bool parseDouble(const std::string& s, double& v) {
  if (s.empty()) return false;
  errno = 0;
  char* end = nullptr;
  v = std::strtod(s.c_str(), &end);
  return end == s.c_str() + s.size() && errno != ERANGE && std::isfinite(v);
}

bool parseInt(const std::string& s, long long& v) {
  if (s.empty()) return false;
  errno = 0;
  char* end = nullptr;
  v = std::strtoll(s.c_str(), &end, 10);
  return end == s.c_str() + s.size() && errno != ERANGE;
}

}  // namespace

TriangleMesh parseObj(const std::string& text, const std::string& name) {
  TriangleMesh mesh;
  std::istringstream in(text);
  std::string raw;
  std::size_t lineNo = 0;
  while (std::getline(in, raw)) {
    ++lineNo;
    const auto hash = raw.find('#');
    if (hash != std::string::npos) raw.resize(hash);
    std::istringstream ls(raw);
    std::string tag;
    if (!(ls >> tag)) continue;
    std::vector<std::string> args;
    for (std::string a; ls >> a;) args.push_back(a);
    if (tag == "v") {
      if (args.size() != 3 && args.size() != 4)
        lineError(name, lineNo, "a vertex needs 3 coordinates (optionally w), got " + std::to_string(args.size()));
      double c[4] = {0, 0, 0, 1};
      for (std::size_t i = 0; i < args.size(); ++i)
        if (!parseDouble(args[i], c[i])) lineError(name, lineNo, "bad vertex coordinate '" + args[i] + "'");
      if (c[3] == 0) lineError(name, lineNo, "vertex weight w must be non-zero");
      mesh.vertices.emplace_back(c[0] / c[3], c[1] / c[3], c[2] / c[3]);
    } else if (tag == "f") {
      if (args.size() < 3) lineError(name, lineNo, "a face needs at least 3 corners, got " + std::to_string(args.size()));
      std::vector<int> idx;
      for (const std::string& a : args) {
        const std::string first = a.substr(0, a.find('/'));
        long long i;
        if (!parseInt(first, i) || i == 0) lineError(name, lineNo, "bad vertex index '" + a + "'");
        const long long n = static_cast<long long>(mesh.vertices.size());
        const long long k = i > 0 ? i - 1 : n + i;  // negative: relative to the last vertex read
        if (k < 0 || k >= n)
          lineError(name, lineNo, "vertex index " + std::to_string(i) + " out of range (" + std::to_string(n) +
                                      " vertices defined so far)");
        idx.push_back(int(k));
      }
      for (std::size_t t = 1; t + 1 < idx.size(); ++t) mesh.triangles.push_back({idx[0], idx[t], idx[t + 1]});
    }
    // Everything else (vt, vn, o, g, s, usemtl, mtllib, l, p, ...) carries no geometry we draw.
  }
  return mesh;
}

TriangleMesh readObj(const std::string& path, std::size_t max_bytes) {
  return parseObj(readModelFile(path, max_bytes, "OBJ file"), path);
}

std::vector<Primitive> meshPrimitives(const TriangleMesh& mesh, std::size_t* skipped, const ViewVolume* view,
                                      ViewCullCount* count) {
  ViewCullCount local(view != nullptr);
  ViewCullCount& seen = count ? *count : local;
  std::vector<Primitive> out;
  out.reserve(mesh.triangles.size());
  std::size_t bad = 0;
  for (const auto& t : mesh.triangles) {
    const Eigen::Vector3d& a = mesh.vertices[std::size_t(t[0])];
    const Eigen::Vector3d& b = mesh.vertices[std::size_t(t[1])];
    const Eigen::Vector3d& c = mesh.vertices[std::size_t(t[2])];
    const double scale = std::max({(b - a).squaredNorm(), (c - a).squaredNorm(), (c - b).squaredNorm()});
    if (!((b - a).cross(c - a).norm() > 1e-12 * scale)) {
      ++bad;
      continue;
    }
    if (view) {
      const Eigen::Vector3d corners[3] = {a, b, c};
      if (!seen.keep(view->mayContain(corners, 3))) continue;
    }
    out.push_back(makeTriangle(a, b, c));
  }
  if (skipped) *skipped = bad;
  return out;
}

std::vector<Primitive> buildTriangleMesh(const JsonNode& o, ObjectContext& ctx) {
  if (ctx.solid) o.at("solid").fail("a triangle mesh is made of facets; solid display is meaningless");
  auto file = o.get("file");
  auto verts = o.get("vertices");
  auto tris = o.get("triangles");
  TriangleMesh mesh;
  if (file) {
    if (verts || tris) (verts ? *verts : *tris).fail("give either 'file' or 'vertices' + 'triangles', not both");
    const std::string path = file->string();
    if (path.empty()) file->fail("file name is empty");
    try {
      mesh = readObj(ctx.resolve(path), ctx.limits.max_input_bytes);
    } catch (const std::runtime_error& e) {
      file->fail(e.what());
    }
  } else {
    if (!verts) o.fail("missing required key 'vertices' (or 'file')");
    if (!tris) o.fail("missing required key 'triangles'");
    for (const JsonNode& v : verts->elements()) mesh.vertices.push_back(v.vec3());
    const long long n = static_cast<long long>(mesh.vertices.size());
    for (const JsonNode& t : tris->elements()) {
      if (t.size() != 3) t.fail("expected 3 vertex indices, got " + std::to_string(t.size()));
      std::array<int, 3> tri{};
      for (std::size_t k = 0; k < 3; ++k) {
        if (n == 0) t[k].fail("no vertices to index");
        tri[k] = int(t[k].integer(0, n - 1));
      }
      mesh.triangles.push_back(tri);
    }
  }
  ViewCullCount seen(ctx.view != nullptr);
  std::vector<Primitive> prims = meshPrimitives(mesh, nullptr, ctx.view, &seen);
  ctx.note = seen.note();
  return prims;
}

namespace {
// The scene object type this modeler provides (loader/object_registry.h).
[[maybe_unused]] const bool kRegistered = registerObjectTypes({
    {"triangle_mesh", buildTriangleMesh},
});

}  // namespace

}  // namespace qacc
