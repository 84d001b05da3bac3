// Coverage errors from the object-id buffers (design §4), test image against reference:
//  - wrong_object: both show a surface but of different scene objects;
//  - pinholes: the reference shows a surface, the test shows background;
//  - spurious: the reference shows background, the test shows a surface.
#pragma once
#include <cstddef>

#include "raster/image/frame_buffer.h"
#include "raster/image/image.h"

namespace qacc {

struct CoverageError {
  std::size_t pixels = 0;              // image size
  std::size_t reference_covered = 0;   // pixels the reference covers
  std::size_t wrong_object = 0;
  std::size_t pinholes = 0;
  std::size_t spurious = 0;
  std::size_t errors() const { return wrong_object + pinholes + spurious; }
  // Fraction of the reference's covered pixels that are wrong or missing in the test.
  double wrongFraction() const {
    return reference_covered ? double(wrong_object + pinholes) / double(reference_covered) : 0.0;
  }
};

// Throws std::invalid_argument when the sizes differ.
CoverageError coverageError(const FrameBuffer& reference, const FrameBuffer& test);
// 1-channel mask image: 0 = agree, 1 = wrong object, 2 = pinhole, 3 = spurious.
Image8 coverageErrorMask(const FrameBuffer& reference, const FrameBuffer& test);

}  // namespace qacc
