#include "raster/pixel/shading.h"

#include <algorithm>
#include <cmath>

namespace qacc {

Eigen::Vector3d shadeLinear(const Scene& scene, const Material& m, const Eigen::Vector3d& p,
                            const Eigen::Vector3d& normal) {
  const Eigen::Vector3d V = scene.camera.toViewer(p);
  Eigen::Vector3d N = normal.normalized();
  if (N.dot(V) < 0) N = -N;  // two-sided
  Eigen::Vector3d out = Eigen::Vector3d::Zero();
  for (const Light& l : scene.lights) {
    if (l.type == Light::Type::Ambient) {
      out += l.color.cwiseProduct(m.color);
      continue;
    }
    const Eigen::Vector3d L = l.type == Light::Type::Directional ? Eigen::Vector3d(-l.direction.normalized())
                                                                 : Eigen::Vector3d((l.position - p).normalized());
    const double ndl = N.dot(L);
    if (ndl <= 0) continue;
    const Eigen::Vector3d H = (L + V).normalized();
    const double spec = m.specular * std::pow(std::max(0.0, N.dot(H)), m.shininess);
    out += l.color.cwiseProduct(m.color * ndl + Eigen::Vector3d::Constant(spec));
  }
  return out;
}

}  // namespace qacc
