// Error heat maps for comparison images: a scalar image mapped through a perceptual ramp
// (black → blue → magenta → orange → yellow → white), 0 → black, `max_value` and above → white.
#pragma once
#include "raster/image/frame_buffer.h"
#include "raster/image/image.h"

namespace qacc {

Image8 heatMap(const ImageF& values, double max_value);
// Per-pixel absolute luma difference |Y(a) − Y(b)| (Rec. 601 on 8-bit sRGB), 0..255.
ImageF lumaDifference(const Image8& a, const Image8& b);
// Copies `src` (RGB or gray) into the RGB image `dst` at (x0, y0), clipped to dst.
void blit(Image8& dst, const Image8& src, int x0, int y0);

}  // namespace qacc
