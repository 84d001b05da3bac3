// The projected chord error of a mesh (screen_error.h).
#include "modeling/tessellation/screen_error.h"

#include <algorithm>
#include <cmath>

#include "modeling/tessellation/tessellation.h"

namespace qacc {

PixelError measurePixelError(const TriangleMesh3& mesh, const Quadric& quadric, const ScreenView& view,
                             std::size_t first, std::size_t count, int subdivisions) {
  PixelError e;
  const std::size_t last =
      std::min(mesh.triangles.size(), count == std::size_t(-1) ? mesh.triangles.size() : first + count);
  const int m = std::max(1, subdivisions);
  const Quadric normalized = quadric.normalized();  // once for all the samples (closestPointOnQuadric's)
  double sum = 0;
  for (std::size_t t = first; t < last; ++t) {
    const Eigen::Vector3d& a = mesh.positions[std::size_t(mesh.triangles[t][0])];
    const Eigen::Vector3d& b = mesh.positions[std::size_t(mesh.triangles[t][1])];
    const Eigen::Vector3d& c = mesh.positions[std::size_t(mesh.triangles[t][2])];
    for (int i = 0; i <= m; ++i)
      for (int j = 0; i + j <= m; ++j) {
        const Eigen::Vector3d p = (double(i) * a + double(j) * b + double(m - i - j) * c) / double(m);
        if (!view.onScreen(p, 2.0)) continue;
        const Eigen::Vector3d q = closestPointOnNormalizedQuadric(normalized, p);
        const Eigen::Vector4d wq = view.window * q.homogeneous();
        if (!(wq.w() > 0)) continue;
        const double d = (view.project(p) - wq.head<2>() / wq.w()).norm();
        e.max = std::max(e.max, d);
        sum += d;
        ++e.samples;
      }
  }
  e.mean = e.samples ? sum / double(e.samples) : 0.0;
  return e;
}

}  // namespace qacc
