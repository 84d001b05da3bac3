// Coverage errors from the object-id buffers (design §4), test image against reference:
//  - wrong_object: both show a surface but of different scene objects;
//  - pinholes: the reference shows a surface, the test shows background;
//  - spurious: the reference shows background, the test shows a surface.
// The error fraction counts every wrong pixel (all three classes) over the union of the
// pixels either image covers, so an image that adds surfaces where the reference has none
// is never reported as accurate.
#pragma once
#include <cstddef>

#include "raster/image/frame_buffer.h"
#include "raster/image/image.h"

namespace qacc {

struct CoverageError {
  std::size_t pixels = 0;              // image size
  std::size_t reference_covered = 0;   // pixels the reference covers
  std::size_t union_covered = 0;       // pixels the reference or the test covers
  std::size_t wrong_object = 0;
  std::size_t pinholes = 0;
  std::size_t spurious = 0;
  std::size_t errors() const { return wrong_object + pinholes + spurious; }
  // Wrong pixels of every class over the pixels either image covers (0 when neither covers any).
  double wrongFraction() const { return union_covered ? double(errors()) / double(union_covered) : 0.0; }
};

// Throws std::invalid_argument when the sizes differ.
CoverageError coverageError(const FrameBuffer& reference, const FrameBuffer& test);
// 1-channel mask image: 0 = agree, 1 = wrong object, 2 = pinhole, 3 = spurious.
Image8 coverageErrorMask(const FrameBuffer& reference, const FrameBuffer& test);

}  // namespace qacc
