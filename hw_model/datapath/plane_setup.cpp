#include "hw_model/datapath/plane_setup.h"

#include <cmath>

namespace qacc {

PlaneSetup quantizePlane(const HalfSpace& plane, int x0, int y0, int width, int height, const HwConfig& cfg,
                         OverflowCounter& ovf) {
  const Eigen::Vector4d& p = plane.p;
  // Value at the centre of pixel (0, 0) at z = 0; IEEE rounding is sign-symmetric, so the
  // opposite plane gets exactly the opposite double.
  const double p00 = p[3] + 0.5 * p[0] + 0.5 * p[1];
  const double bound = std::fabs(p[0]) * width + std::fabs(p[1]) * height + std::fabs(p00) + std::fabs(p[2]);
  const int sc = blockExponent(bound, cfg.clip_bits - 2) + cfg.interp_frac_bits;
  const int wd = cfg.clip_bits + cfg.interp_frac_bits + 2;
  PlaneSetup ps;
  ps.owns = plane.owns_boundary;
  const i128 pu = quantize(p[0], sc, wd, cfg.overflow, ovf), pv = quantize(p[1], sc, wd, cfg.overflow, ovf);
  const i128 c = quantize(p00, sc, wd, cfg.overflow, ovf) + pu * i128(x0) + pv * i128(y0);
  ps.h = {pu, pv, fitWidth(c, wd, cfg.overflow, ovf)};
  ps.pz = quantize(p[2], sc, wd, cfg.overflow, ovf);
  ps.zdir = ps.pz > 0 ? 1 : (ps.pz < 0 ? -1 : 0);
  return ps;
}

}  // namespace qacc
