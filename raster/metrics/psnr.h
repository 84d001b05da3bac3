// Peak signal-to-noise ratio between two 8-bit images (design §4):
// PSNR = 10 log10(255² / MSE) over every channel of every pixel; +inf when identical.
#pragma once
#include "raster/image/frame_buffer.h"
#include "raster/image/image.h"

namespace qacc {

// Mean squared error over all samples (channels included). Throws std::invalid_argument
// when the shapes differ.
double meanSquaredError(const Image8& a, const Image8& b);
// PSNR in dB; std::numeric_limits<double>::infinity() for identical images.
double psnr(const Image8& a, const Image8& b);
inline double psnr(const FrameBuffer& reference, const FrameBuffer& test) {
  return psnr(reference.color, test.color);
}

}  // namespace qacc
