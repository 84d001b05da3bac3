// Chord error of a mesh against a quadric (tessellation.h): Newton projection along the
// gradient of sample points of every triangle.
#include <algorithm>
#include <cmath>

#include "modeling/tessellation/tessellation.h"

namespace qacc {

Vector3d closestPointOnQuadric(const Quadric& quadric, const Vector3d& p) {
  return closestPointOnNormalizedQuadric(quadric.normalized(), p);
}

Vector3d closestPointOnNormalizedQuadric(const Quadric& q, const Vector3d& p) {
  Vector3d x = p;
  for (int it = 0; it < 30; ++it) {
    const double f = q.eval(x);
    const Vector3d g = q.gradient(x);
    const double g2 = g.squaredNorm();
    if (!(g2 > 1e-300)) break;
    const Vector3d step = f * g / g2;
    x -= step;
    if (step.norm() <= 1e-14 * (1.0 + x.norm())) break;
  }
  return x;
}

double distanceToQuadric(const Quadric& quadric, const Vector3d& p) { return (closestPointOnQuadric(quadric, p) - p).norm(); }

ChordError measureChordError(const TriangleMesh3& mesh, const Quadric& quadric, std::size_t first, std::size_t count,
                             int subdivisions) {
  ChordError e;
  const std::size_t last = std::min(mesh.triangles.size(), count == std::size_t(-1) ? mesh.triangles.size() : first + count);
  const int m = std::max(1, subdivisions);  // barycentric grid: vertices, edge points, interior points
  const Quadric q = quadric.normalized();   // once for all the samples (distanceToQuadric's projection)
  double sum = 0;
  std::size_t samples = 0;
  for (std::size_t t = first; t < last; ++t) {
    const Vector3d& a = mesh.positions[std::size_t(mesh.triangles[t][0])];
    const Vector3d& b = mesh.positions[std::size_t(mesh.triangles[t][1])];
    const Vector3d& c = mesh.positions[std::size_t(mesh.triangles[t][2])];
    for (int i = 0; i <= m; ++i)
      for (int j = 0; i + j <= m; ++j) {
        const Vector3d p = (double(i) * a + double(j) * b + double(m - i - j) * c) / double(m);
        const double d = (closestPointOnNormalizedQuadric(q, p) - p).norm();
        e.max = std::max(e.max, d);
        sum += d;
        ++samples;
      }
  }
  e.mean = samples ? sum / double(samples) : 0.0;
  return e;
}

}  // namespace qacc
