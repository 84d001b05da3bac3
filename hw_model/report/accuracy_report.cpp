#include "hw_model/report/accuracy_report.h"

#include <cstdio>

#include "raster/metrics/coverage_error.h"
#include "raster/metrics/depth_error.h"
#include "raster/metrics/psnr.h"

namespace qacc {

AccuracyReport accuracyReport(const FrameBuffer& reference, const FrameBuffer& test, const Camera& camera,
                              int zbufferBits) {
  AccuracyReport r;
  const CoverageError ce = coverageError(reference, test);
  r.reference_covered = ce.reference_covered;
  r.wrong_object = ce.wrong_object;
  r.pinholes = ce.pinholes;
  r.spurious = ce.spurious;
  r.wrong_fraction = ce.wrongFraction();
  const DepthError de = depthError(reference, test, camera, zbufferBits);
  r.max_depth_lsb = de.max_lsb;
  r.mean_depth_lsb = de.mean_lsb;
  r.psnr_db = psnr(reference, test);
  return r;
}

std::string AccuracyReport::line() const {
  char buf[400];
  std::snprintf(buf, sizeof buf,
                "accuracy vs reference: %zu wrong-object pixels, %zu pinholes, %zu spurious (%.4f%% of %zu covered), "
                "depth error max %.2f / mean %.3f Z LSBs, PSNR %.2f dB",
                wrong_object, pinholes, spurious, 100.0 * wrong_fraction, reference_covered, max_depth_lsb,
                mean_depth_lsb, psnr_db);
  return buf;
}

}  // namespace qacc
