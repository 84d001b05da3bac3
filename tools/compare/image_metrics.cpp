#include "tools/compare/image_metrics.h"

#include <cmath>

#include "raster/metrics/coverage_error.h"
#include "raster/metrics/depth_error.h"
#include "raster/metrics/psnr.h"
#include "raster/metrics/silhouette_distance.h"
#include "raster/metrics/ssim.h"

namespace qacc::compare {

Metrics measure(const FrameBuffer& ref, const FrameBuffer& t, const Camera& cam, int zbits) {
  Metrics m;
  m.psnr = psnr(ref, t);
  m.ssim = ssim(ref, t);
  const CoverageError c = coverageError(ref, t);
  m.wrong = c.wrong_object;
  m.pinholes = c.pinholes;
  m.spurious = c.spurious;
  const SilhouetteDistance s = silhouetteDistance(ref, t);
  m.hausdorff = s.hausdorff;
  m.chamfer = s.mean;
  const DepthError d = depthError(ref, t, cam, zbits);
  m.depth_mean_lsb = d.mean_lsb;
  m.depth_max_lsb = d.max_lsb;
  return m;
}

const std::vector<MetricDef>& metricDefs() {
  static const std::vector<MetricDef> defs = {
      {"psnr_db", "PSNR dB", true, [](const Metrics& m) { return m.psnr; }},
      {"ssim", "SSIM", true, [](const Metrics& m) { return m.ssim; }},
      {"coverage_px", "coverage errors px", false, [](const Metrics& m) { return m.coverage(); }},
      {"silhouette_hausdorff_px", "silhouette Hausdorff px", false, [](const Metrics& m) { return m.hausdorff; }},
      {"silhouette_mean_px", "silhouette mean px", false, [](const Metrics& m) { return m.chamfer; }},
      {"depth_mean_lsb", "depth mean LSB", false, [](const Metrics& m) { return m.depth_mean_lsb; }},
  };
  return defs;
}

bool noWorse(const MetricDef& d, double v, double ref) {
  if (std::isnan(v) || std::isnan(ref)) return false;
  return d.higher_better ? v >= ref : v <= ref;
}

}  // namespace qacc::compare
