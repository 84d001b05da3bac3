// Small images for the sweep report: a box-filtered thumbnail of a render, and an error
// map (luma difference as a heat map, with coverage errors painted over it: wrong object
// red, pinhole yellow, spurious cyan) reduced by keeping the worst pixel of each block, so
// that a single wrong pixel stays visible in the thumbnail.
#pragma once
#include "raster/image/frame_buffer.h"
#include "raster/image/image.h"

namespace qacc {

Image8 thumbnail(const Image8& rgb, int maxWidth);
Image8 errorMapThumbnail(const FrameBuffer& reference, const FrameBuffer& test, int maxWidth);

}  // namespace qacc
