// Watertightness of a mesh (tessellation.h): vertices identified by exact position, every
// undirected edge used by exactly two triangles, no degenerate triangle.
#include <algorithm>
#include <map>
#include <utility>

#include "modeling/tessellation/surface_clipping.h"  // PointKey
#include "modeling/tessellation/tessellation.h"

namespace qacc {

bool isWatertight(const TriangleMesh3& mesh) {
  std::map<Vector3d, int, tess::PointKey> ids;
  auto id = [&](const Vector3d& p) {
    auto it = ids.find(p);
    if (it != ids.end()) return it->second;
    const int n = int(ids.size());
    ids.emplace(p, n);
    return n;
  };
  std::map<std::pair<int, int>, int> edges;
  for (const auto& t : mesh.triangles) {
    int v[3];
    for (int k = 0; k < 3; ++k) v[k] = id(mesh.positions[std::size_t(t[k])]);
    if (v[0] == v[1] || v[1] == v[2] || v[0] == v[2]) return false;
    for (int k = 0; k < 3; ++k) {
      const int a = v[k], b = v[(k + 1) % 3];
      edges[{std::min(a, b), std::max(a, b)}]++;
    }
  }
  if (edges.empty()) return false;
  for (const auto& e : edges)
    if (e.second != 2) return false;
  return true;
}

}  // namespace qacc
