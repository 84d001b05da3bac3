// What travels on the channels of the cycle engine. The datapath results a token needs
// come from the pixel trace (engines/pixel_trace.h), computed beforehand by the same
// arithmetic as `hw`; tokens only say which pixel of which primitive is where.
#pragma once
#include <cstdint>

#include "hw_model/datapath/fixed_point.h"

namespace qacc {

// A primitive, by index, from the host interface to setup and from setup to traversal.
using PrimitiveToken = int;

// A pixel issued by traversal to a pixel pipeline.
struct PixelToken {
  int prim = 0;
  int x = 0, y = 0;
  int k = 0;  // issue order within the primitive: its entry in the pixel trace
};

// A visible point of a primitive on a pixel: from a pixel pipeline to the Z-buffer, and
// from the Z-buffer (when it passed the depth test) to shading.
struct PointToken {
  int prim = 0;
  int x = 0, y = 0;
  int cap = -1;  // cap plane, -1 for a surface point
  std::int64_t z = 0;  // depth, internal format (|z| < 2^(depth_bits - 1), depth_bits <= 40: clampDepth)
};

}  // namespace qacc
