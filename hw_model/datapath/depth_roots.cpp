#include "hw_model/datapath/depth_roots.h"

namespace qacc {

namespace {
template <Rounding R>
DepthRoots depthRootsRounded(const PrimitiveSetup& s, const HwConfig& cfg, i128 b, i128 c, i128 sq,
                             OverflowCounters& ovf) {
  if (cfg.depth_variant == DepthVariant::Stable) return depthRootsT<R, DepthVariant::Stable>(s, cfg, b, c, sq, ovf);
  return depthRootsT<R, DepthVariant::Reciprocal>(s, cfg, b, c, sq, ovf);
}
}  // namespace

DepthRoots depthRoots(const PrimitiveSetup& s, const HwConfig& cfg, i128 b, i128 c, i128 sq, OverflowCounters& ovf) {
  switch (cfg.rounding) {
    case Rounding::Truncate: return depthRootsRounded<Rounding::Truncate>(s, cfg, b, c, sq, ovf);
    case Rounding::Nearest: return depthRootsRounded<Rounding::Nearest>(s, cfg, b, c, sq, ovf);
    case Rounding::NearestEven: break;
  }
  return depthRootsRounded<Rounding::NearestEven>(s, cfg, b, c, sq, ovf);
}

}  // namespace qacc
