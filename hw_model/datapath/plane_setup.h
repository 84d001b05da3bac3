// quantizePlane: the setup of one clip plane (design §3.2 step 2) — its value
// h(u, v) + pz z at the pixel centres of the primitive's box, in integers.
//
// Boundary ownership (half_space.h, docs/HW_MODEL.md) asks that a plane and its opposite,
// used by two cells that share a face, keep complementary sets of pixel centres: neither
// both drop a centre on the plane (a pinhole) nor both keep it. Integers make that exact
// only if the two cells' plane values are exact negations at every pixel. So the plane is
// quantised from the plane and the screen alone — its value at the centre of pixel (0, 0),
// its steps per pixel in x and y and its z coefficient, one block exponent from the
// plane's largest value over the screen — never from the primitive's box (each cell has
// its own box, and a box-dependent origin or exponent rounds the two cells differently).
// Rounding is to nearest, ties away from zero, or truncation toward zero: both symmetric,
// so quantize(-p) = -quantize(p). The seed of the box corner (x0, y0) is then formed in
// integers, exactly: the value at a given pixel does not depend on the box.
#pragma once
#include "hw_model/config/hw_config.h"
#include "hw_model/datapath/fixed_point.h"
#include "hw_model/datapath/primitive_setup.h"
#include "modeling/geometry/half_space.h"

namespace qacc {

// h (seeded at the box corner (x0, y0)), pz, zdir and owns of the window-space half-space
// `plane` (x right, y down, pixel centres at + 0.5) on a width x height screen.
PlaneSetup quantizePlane(const HalfSpace& plane, int x0, int y0, int width, int height, const HwConfig& cfg,
                         OverflowCounter& ovf);

}  // namespace qacc
