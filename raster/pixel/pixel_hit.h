// The exact visible point of one window-space primitive on the line of one pixel
// (design §3.1): the first depth z in [0, 1] along +z where
//  - surface mode: f(z) = 0 and every clip half-space keeps (x, y, z);
//  - solid mode: the line enters {f <= 0} ∩ clip polyhedron. If it enters through one of
//    the primitive's own clip planes the hit is a cap (normal = that plane's normal); if it
//    is already inside at the near plane (eye inside the solid) the first surface point
//    beyond is shown, as in surface mode: caps live only on the primitive's own planes.
#pragma once
#include "raster/pixel/window_primitive.h"

namespace qacc {

struct PixelHit {
  double z = 0;
  int cap = -1;  // index of the clip plane of a cap, -1 for a surface point
};

bool pixelHit(const WindowPrimitive& w, double x, double y, PixelHit& hit);

}  // namespace qacc
