// Accuracy of an image against the reference, the same everywhere it is printed or saved
// (`qacc render` after every render of a non-reference engine, `--stats`, `qacc sweep`,
// `qacc autosize`). Uses the metrics of raster/metrics:
//  - coverage (coverage_error.h): wrong-object pixels, pinholes (reference shows a surface,
//    the image none), spurious pixels (the image shows a surface, the reference none), and
//    the error fraction: all three over the union of the pixels either image covers;
//  - depth (depth_error.h), where both show the same object, in units that do not depend on
//    the configuration: window depth x 2^24 ("z24") and world units along the view axis;
//  - PSNR, SSIM, silhouette Hausdorff and mean distance (pixels).
#pragma once
#include <string>
#include <utility>
#include <vector>

#include "modeling/scene/camera.h"
#include "raster/image/frame_buffer.h"

namespace qacc {

struct AccuracyReport {
  std::size_t reference_covered = 0;
  std::size_t union_covered = 0;  // pixels the reference or the image covers
  std::size_t wrong_object = 0;
  std::size_t pinholes = 0;
  std::size_t spurious = 0;
  double wrong_fraction = 0;  // (wrong + pinholes + spurious) / union covered
  double max_depth_z24 = 0, mean_depth_z24 = 0;      // window depth x 2^24
  double max_depth_world = 0, mean_depth_world = 0;  // world units along the view axis
  double psnr_db = 0;
  double ssim = 0;
  double silhouette_hausdorff = 0, silhouette_mean = 0;  // pixels
  std::string line() const;
  // Every figure as (key, value), in a fixed order: the JSON "accuracy" block and CSV columns.
  std::vector<std::pair<std::string, double>> fields() const;
};

AccuracyReport accuracyReport(const FrameBuffer& reference, const FrameBuffer& test, const Camera& camera);

}  // namespace qacc
