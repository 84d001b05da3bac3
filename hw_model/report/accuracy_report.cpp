#include "hw_model/report/accuracy_report.h"

#include <cstdio>

#include "raster/metrics/coverage_error.h"
#include "raster/metrics/depth_error.h"
#include "raster/metrics/psnr.h"
#include "raster/metrics/silhouette_distance.h"
#include "raster/metrics/ssim.h"

namespace qacc {

AccuracyReport accuracyReport(const FrameBuffer& reference, const FrameBuffer& test, const Camera& camera) {
  AccuracyReport r;
  const CoverageError ce = coverageError(reference, test);
  r.reference_covered = ce.reference_covered;
  r.union_covered = ce.union_covered;
  r.wrong_object = ce.wrong_object;
  r.pinholes = ce.pinholes;
  r.spurious = ce.spurious;
  r.wrong_fraction = ce.wrongFraction();
  const DepthError de = depthError(reference, test, camera);
  r.max_depth_z24 = de.max_z24;
  r.mean_depth_z24 = de.mean_z24;
  r.max_depth_world = de.max_view;
  r.mean_depth_world = de.mean_view;
  r.psnr_db = psnr(reference, test);
  r.ssim = ssim(reference, test);
  const SilhouetteDistance sd = silhouetteDistance(reference, test);
  r.silhouette_hausdorff = sd.hausdorff;
  r.silhouette_mean = sd.mean;
  return r;
}

std::string AccuracyReport::line() const {
  char buf[600];
  std::snprintf(buf, sizeof buf,
                "accuracy vs reference: %.4f%% wrong (%zu wrong-object, %zu pinholes, %zu spurious of %zu pixels "
                "covered by either), depth error max %.2f / mean %.3f z24 (window depth x 2^24; %.3g / %.3g world "
                "units), PSNR %.2f dB, SSIM %.5f, silhouette Hausdorff %.2f / mean %.3f px",
                100.0 * wrong_fraction, wrong_object, pinholes, spurious, union_covered, max_depth_z24,
                mean_depth_z24, max_depth_world, mean_depth_world, psnr_db, ssim, silhouette_hausdorff,
                silhouette_mean);
  return buf;
}

std::vector<std::pair<std::string, double>> AccuracyReport::fields() const {
  return {{"wrong_percent", 100.0 * wrong_fraction},
          {"wrong_object", double(wrong_object)},
          {"pinholes", double(pinholes)},
          {"spurious", double(spurious)},
          {"reference_covered", double(reference_covered)},
          {"union_covered", double(union_covered)},
          {"psnr_db", psnr_db},
          {"ssim", ssim},
          {"silhouette_hausdorff_px", silhouette_hausdorff},
          {"silhouette_mean_px", silhouette_mean},
          {"depth_max_z24", max_depth_z24},
          {"depth_mean_z24", mean_depth_z24},
          {"depth_max_world", max_depth_world},
          {"depth_mean_world", mean_depth_world}};
}

}  // namespace qacc
