// The depth intervals of one solid window-space primitive along the line of one pixel:
// {f <= 0} ∩ clip polyhedron ∩ [0, 1] as at most two closed intervals, each end tagged
// with what bounds it there: the quadric surface, one of the primitive's own clip planes
// (a cap) or the near / far plane of the view volume (no boundary of the solid). The
// same interval logic as pixelHit (pixel_hit.h) in solid mode, kept whole because a
// Boolean combination (CSG) needs every entry and exit, not only the first.
#pragma once
#include "raster/pixel/window_primitive.h"

namespace qacc {

struct DepthBound {
  static constexpr int kSurface = -1;  // the quadric surface
  static constexpr int kView = -2;     // the near (z = 0) or far (z = 1) plane
  double z = 0;
  int tag = kSurface;  // kSurface, kView or the index of the clip plane (a cap)
};

struct DepthInterval {
  DepthBound in, out;  // in.z <= out.z
};

// Writes up to 2 intervals of positive length in increasing depth; returns how many.
int solidIntervals(const WindowPrimitive& w, double x, double y, DepthInterval out[2]);

}  // namespace qacc
