#include "modeling/tessellation/facet_scene.h"

#include "modeling/geometry/natural_quadrics.h"

namespace qacc {

Scene facetScene(const Scene& scene, const TriangleMesh3& mesh) {
  Scene out = scene;
  out.primitives.clear();
  out.exact_surfaces.clear();
  out.primitives.reserve(mesh.size());
  for (std::size_t t = 0; t < mesh.size(); ++t) {
    const auto& tri = mesh.triangles[t];
    const Eigen::Vector3d& a = mesh.positions[std::size_t(tri[0])];
    const Eigen::Vector3d& b = mesh.positions[std::size_t(tri[1])];
    const Eigen::Vector3d& c = mesh.positions[std::size_t(tri[2])];
    if (!((b - a).cross(c - a).norm() > 0)) continue;
    Primitive p = makeTriangle(a, b, c);
    p.object = t < mesh.object.size() ? mesh.object[t] : 0;
    p.material = t < mesh.material.size() ? mesh.material[t] : 0;
    out.primitives.push_back(p);
  }
  // Objects: the range of facets each produced (facets come out in primitive order).
  for (auto& o : out.objects) {
    o.count = 0;
    o.exact_surface = -1;
  }
  for (std::size_t i = 0; i < out.primitives.size(); ++i) {
    const int o = out.primitives[i].object;
    if (o < 0 || std::size_t(o) >= out.objects.size()) continue;
    if (out.objects[std::size_t(o)].count == 0) out.objects[std::size_t(o)].first = i;
    out.objects[std::size_t(o)].count = i + 1 - out.objects[std::size_t(o)].first;
  }
  return out;
}

}  // namespace qacc
