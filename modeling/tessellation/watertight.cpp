// Watertightness of a mesh (tessellation.h): vertices identified by exact position, every
// undirected edge used by exactly two triangles, no degenerate triangle; and the edges that
// are not (edgeUse), for meshes with an outer boundary.
#include <algorithm>
#include <map>
#include <utility>

#include "modeling/tessellation/surface_clipping.h"  // PointKey
#include "modeling/tessellation/tessellation.h"

namespace qacc {

EdgeUse edgeUse(const TriangleMesh3& mesh) {
  EdgeUse use;
  std::map<Vector3d, int, tess::PointKey> ids;
  std::vector<const Vector3d*> points;
  auto id = [&](const Vector3d& p) {
    auto it = ids.find(p);
    if (it != ids.end()) return it->second;
    const int n = int(ids.size());
    ids.emplace(p, n);
    points.push_back(&p);
    return n;
  };
  std::map<std::pair<int, int>, std::pair<int, std::size_t>> edges;  // uses, last triangle
  for (std::size_t t = 0; t < mesh.triangles.size(); ++t) {
    int v[3];
    for (int k = 0; k < 3; ++k) v[k] = id(mesh.positions[std::size_t(mesh.triangles[t][k])]);
    if (v[0] == v[1] || v[1] == v[2] || v[0] == v[2]) {
      ++use.degenerate;
      continue;
    }
    for (int k = 0; k < 3; ++k) {
      auto& e = edges[{std::min(v[k], v[(k + 1) % 3]), std::max(v[k], v[(k + 1) % 3])}];
      ++e.first;
      e.second = t;
    }
  }
  use.edges = edges.size();
  for (const auto& [key, e] : edges) {
    if (e.first == 1) use.open.push_back({*points[std::size_t(key.first)], *points[std::size_t(key.second)], e.second});
    if (e.first > 2) ++use.overused;
  }
  return use;
}

bool isWatertight(const TriangleMesh3& mesh) {
  const EdgeUse use = edgeUse(mesh);
  return use.edges > 0 && use.degenerate == 0 && use.open.empty() && use.overused == 0;
}

}  // namespace qacc
