// Structural similarity (Wang, Bovik, Sheikh, Simoncelli 2004) on luma (design §4):
// 11x11 circular-symmetric Gaussian window with σ = 1.5 (normalised to sum 1),
// K1 = 0.01, K2 = 0.03, L = 255, C1 = (K1 L)², C2 = (K2 L)²,
//   SSIM(x, y) = (2 μx μy + C1)(2 σxy + C2) / ((μx² + μy² + C1)(σx² + σy² + C2)),
// evaluated at every pixel whose window lies wholly inside the image ("valid" region, as
// in the authors' reference implementation) and averaged (MSSIM). Images smaller than the
// window use the window truncated at the image border and renormalised.
// Luma is Rec. 601 Y' = 0.299 R' + 0.587 G' + 0.114 B' on the 8-bit sRGB values.
#pragma once
#include "raster/image/frame_buffer.h"
#include "raster/image/image.h"

namespace qacc {

struct SsimResult {
  double mean = 1.0;  // MSSIM
  ImageF map;         // per-pixel SSIM (size of the input; border pixels outside the valid
                      // region hold the value of the nearest valid pixel)
};

// Luma of an 8-bit RGB (3 channels) or gray (1 channel) image, as doubles in [0, 255].
ImageF luma(const Image8& img);
SsimResult ssimMap(const Image8& a, const Image8& b);
double ssim(const Image8& a, const Image8& b);
inline double ssim(const FrameBuffer& reference, const FrameBuffer& test) {
  return ssim(reference.color, test.color);
}

}  // namespace qacc
