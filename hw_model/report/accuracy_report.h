// Accuracy of an accelerator image against the reference (issue 3, item 6), printed after
// every hw / hw-cycle render: wrong-object pixels, pinholes (reference shows a surface,
// accelerator shows background), maximum and mean depth error in Z-buffer LSBs, PSNR.
// Uses the metrics of raster/ (coverage_error.h, depth_error.h, psnr.h).
#pragma once
#include <string>
#include <vector>

#include "modeling/scene/camera.h"
#include "raster/image/frame_buffer.h"

namespace qacc {

struct AccuracyReport {
  std::size_t reference_covered = 0;
  std::size_t wrong_object = 0;
  std::size_t pinholes = 0;
  std::size_t spurious = 0;
  double wrong_fraction = 0;  // (wrong + pinholes) / reference covered
  double max_depth_lsb = 0, mean_depth_lsb = 0;
  double psnr_db = 0;
  std::string line() const;
};

AccuracyReport accuracyReport(const FrameBuffer& reference, const FrameBuffer& test, const Camera& camera,
                              int zbufferBits);

}  // namespace qacc
