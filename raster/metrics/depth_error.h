// Depth error (design §4) over the pixels where the reference and the test hit the same
// scene object: |z_ref − z_test| in window depth units ([0, 1]), in Z-buffer LSBs of a
// `bits`-bit buffer (window depth × (2^bits − 1)), in units independent of any
// configuration (window depth × 2^24, `z24`: what accuracy reports print, so that a narrow
// Z-buffer never looks better for its coarser LSB), and in view units (distance along the
// viewing axis, recovered from window depth through the camera's near/far: world units).
#pragma once
#include <cstddef>

#include "modeling/scene/camera.h"
#include "raster/image/frame_buffer.h"
#include "raster/image/image.h"

namespace qacc {

struct DepthError {
  std::size_t pixels = 0;  // pixels where both hit the same object
  double max_window = 0, mean_window = 0;
  double max_lsb = 0, mean_lsb = 0;
  double max_z24 = 0, mean_z24 = 0;  // window depth x 2^24
  double max_view = 0, mean_view = 0;
  int bits = 24;
};

// View-axis distance from the eye of a window depth z in [0, 1] for this camera.
double windowDepthToView(const Camera& camera, double z);
DepthError depthError(const FrameBuffer& reference, const FrameBuffer& test, const Camera& camera,
                      int bits = 24);
// |Δz| in window units where both hit the same object, 0 elsewhere (for heat maps).
ImageF depthErrorMap(const FrameBuffer& reference, const FrameBuffer& test);

}  // namespace qacc
