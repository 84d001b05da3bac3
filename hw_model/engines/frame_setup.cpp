#include "hw_model/engines/frame_setup.h"

#include <omp.h>

#include <cmath>

#include "hw_model/datapath/setup_arithmetic.h"

namespace qacc {

FrameSetup FrameSetup::build(const Scene& scene, const HwConfig& cfg, int threads) {
  FrameSetup fs;
  const int n = int(scene.primitives.size());
  fs.setups.resize(std::size_t(n));
  const Eigen::Matrix4d M = scene.camera.worldToWindow(scene.width, scene.height);
  const Eigen::Matrix4d Minv = M.inverse();
  std::vector<OverflowCounter> ovf(static_cast<std::size_t>(n));
  const int nt = threads > 0 ? threads : omp_get_max_threads();
#pragma omp parallel for schedule(dynamic, 16) num_threads(nt)
  for (int i = 0; i < n; ++i) fs.setups[std::size_t(i)] = setupPrimitive(scene, i, M, Minv, cfg, ovf[std::size_t(i)]);
  for (const auto& o : ovf) {
    fs.overflow.setup.events += o.events;
    fs.overflow.setup.zeroed += o.zeroed;
    fs.overflow.setup.coarse += o.coarse;
  }
  fs.lighting = LightingSetup::build(scene, cfg, fs.overflow.shading);
  fs.storedDepthStep = std::ldexp(1.0, -cfg.zbuffer_bits);
  return fs;
}

}  // namespace qacc
