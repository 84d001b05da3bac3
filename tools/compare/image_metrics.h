// The errors of an image against the reference that `qacc compare` measures (PSNR, SSIM,
// coverage errors, silhouette distances, depth error), and the six the tables and plots
// compare, each with its key, label and direction.
#pragma once
#include <cstddef>
#include <functional>
#include <vector>

#include "modeling/scene/camera.h"
#include "raster/image/frame_buffer.h"

namespace qacc::compare {

struct Metrics {
  double psnr = 0, ssim = 0;
  std::size_t wrong = 0, pinholes = 0, spurious = 0;
  double hausdorff = 0, chamfer = 0;
  double depth_mean_lsb = 0, depth_max_lsb = 0;
  double coverage() const { return double(wrong + pinholes + spurious); }
};

Metrics measure(const FrameBuffer& ref, const FrameBuffer& t, const Camera& cam, int zbits);

struct MetricDef {
  const char* key;
  const char* label;
  bool higher_better;
  std::function<double(const Metrics&)> get;
};
const std::vector<MetricDef>& metricDefs();

// v is at least as good as ref (false when either is NaN).
bool noWorse(const MetricDef& d, double v, double ref);

}  // namespace qacc::compare
