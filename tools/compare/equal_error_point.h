// Where the facets reach a target error (the accelerator's), from the measured settings only:
// the measured costs (triangles) and errors, coarse to fine. The answer is a position between
// two measured settings, interpolated in log cost — error ∝ cost^b for lower-better errors
// (linear when an error or the target is 0), PSNR linear in log cost, 1 − SSIM ∝ cost^b —
// and never more than one step (the ratio of the two finest costs) beyond the finest
// measured; beyond that it is "not reached" and the finest measured is the answer given. A
// target of 0 (or a measured 0) is interpolated linearly but never extrapolated.
#pragma once
#include <cstddef>
#include <string>
#include <vector>

namespace qacc::compare {

struct MeasuredError {
  double cost = 0;   // triangles (> 0)
  double error = 0;  // the metric; NaN = not measured (skipped)
};

enum class ErrorScale { Log, Linear, OneMinusLog };  // lower-better power law, PSNR, SSIM

enum class EqualErrorStatus {
  AtCoarsest,    // the coarsest measured setting already reaches it (the answer is an upper bound)
  Interpolated,  // between two measured settings (t in (0, 1]; t = 1 is the finer one exactly)
  Extrapolated,  // beyond the finest, at most one step (t in (1, 2])
  NotReached,    // not within one step of the finest: the finest measured is given instead
};
const char* equalErrorStatusName(EqualErrorStatus s);

struct EqualErrorPoint {
  EqualErrorStatus status = EqualErrorStatus::NotReached;
  std::size_t lo = 0, hi = 0;  // indices into the measured list; lo == hi for AtCoarsest
  double t = 0;                // position from lo (0) to hi (1) in log cost; > 1 beyond hi
  double cost = 0;             // the estimated cost at equal error (NotReached: NaN)
  std::size_t finest = 0;      // index of the finest measured (NotReached: the answer given)
  bool found() const { return status != EqualErrorStatus::NotReached; }
};

// `higherBetter`: PSNR, SSIM. Throws std::invalid_argument when nothing was measured.
EqualErrorPoint equalErrorPoint(const std::vector<MeasuredError>& measured, double target, bool higherBetter,
                                ErrorScale scale);

// A quantity measured at lo and hi (e.g. facet cycles, draw time), taken at the point:
// interpolated in log-log along the same t (linear when either is not positive); at lo for
// AtCoarsest, at the finest for NotReached.
double atPoint(const EqualErrorPoint& p, const std::vector<double>& values);

}  // namespace qacc::compare
