#include "tools/compare/equal_error_point.h"

#include <algorithm>
#include <cmath>
#include <numeric>
#include <stdexcept>

namespace qacc::compare {

const char* equalErrorStatusName(EqualErrorStatus s) {
  switch (s) {
    case EqualErrorStatus::AtCoarsest: return "at_coarsest";
    case EqualErrorStatus::Interpolated: return "interpolated";
    case EqualErrorStatus::Extrapolated: return "extrapolated_one_step";
    case EqualErrorStatus::NotReached: return "not_reached";
  }
  return "?";
}

namespace {

bool meets(double v, double target, bool higherBetter) { return higherBetter ? v >= target : v <= target; }

// The error on the scale where it is about linear in log cost; the pair falls back to the
// linear scale when the log of one of them is not finite.
double onScale(double v, ErrorScale s) {
  switch (s) {
    case ErrorScale::Linear: return v;
    case ErrorScale::Log: return v > 0 ? std::log(v) : NAN;
    case ErrorScale::OneMinusLog: return v < 1 ? std::log(1 - v) : NAN;
  }
  return NAN;
}

// t where the error crosses the target on the segment a → b (0 at a, 1 at b); NaN when flat.
double crossing(double ea, double eb, double target, ErrorScale s) {
  double ya = onScale(ea, s), yb = onScale(eb, s), yt = onScale(target, s);
  if (!std::isfinite(ya) || !std::isfinite(yb) || !std::isfinite(yt)) {
    ya = ea;
    yb = eb;
    yt = target;
  }
  if (yb == ya) return NAN;
  return (yt - ya) / (yb - ya);
}

}  // namespace

EqualErrorPoint equalErrorPoint(const std::vector<MeasuredError>& measured, double target, bool higherBetter,
                                ErrorScale scale) {
  // Measured settings with an error, by cost (coarse to fine).
  std::vector<std::size_t> idx;
  for (std::size_t i = 0; i < measured.size(); ++i)
    if (!std::isnan(measured[i].error) && measured[i].cost > 0) idx.push_back(i);
  if (idx.empty()) throw std::invalid_argument("equal error: no measured setting");
  std::stable_sort(idx.begin(), idx.end(), [&](std::size_t a, std::size_t b) { return measured[a].cost < measured[b].cost; });
  EqualErrorPoint p;
  p.finest = idx.back();
  auto costAt = [&](std::size_t lo, std::size_t hi, double t) {
    return std::exp(std::log(measured[lo].cost) + t * (std::log(measured[hi].cost) - std::log(measured[lo].cost)));
  };
  if (std::isnan(target)) {
    p.cost = NAN;
    return p;
  }
  for (std::size_t k = 0; k < idx.size(); ++k) {
    if (!meets(measured[idx[k]].error, target, higherBetter)) continue;
    if (k == 0) {
      p.status = EqualErrorStatus::AtCoarsest;
      p.lo = p.hi = idx[0];
      p.cost = measured[idx[0]].cost;
      return p;
    }
    p.lo = idx[k - 1];
    p.hi = idx[k];
    double t = crossing(measured[p.lo].error, measured[p.hi].error, target, scale);
    if (!std::isfinite(t)) t = 1;
    p.t = std::clamp(t, 0.0, 1.0);
    if (p.t == 0) p.t = 1;  // the coarser one does not meet it: at most the finer one
    p.status = EqualErrorStatus::Interpolated;
    p.cost = costAt(p.lo, p.hi, p.t);
    return p;
  }
  // Not reached by any measured setting: at most one step beyond the finest.
  p.cost = NAN;
  if (idx.size() < 2) return p;
  p.lo = idx[idx.size() - 2];
  p.hi = idx.back();
  if (!(measured[p.hi].cost > measured[p.lo].cost)) return p;
  // Only on the metric's own scale: a power law never reaches an error of 0, so a zero target
  // (or a zero error) is not extrapolated by the linear fallback.
  if (!std::isfinite(onScale(measured[p.lo].error, scale)) || !std::isfinite(onScale(measured[p.hi].error, scale)) ||
      !std::isfinite(onScale(target, scale)))
    return p;
  const double t = crossing(measured[p.lo].error, measured[p.hi].error, target, scale);
  if (std::isfinite(t) && t > 1 && t <= 2) {
    p.status = EqualErrorStatus::Extrapolated;
    p.t = t;
    p.cost = costAt(p.lo, p.hi, t);
  }
  return p;
}

double atPoint(const EqualErrorPoint& p, const std::vector<double>& values) {
  if (p.status == EqualErrorStatus::NotReached) return values.at(p.finest);
  const double a = values.at(p.lo), b = values.at(p.hi);
  if (p.status == EqualErrorStatus::AtCoarsest || p.t == 0) return a;
  if (p.t == 1) return b;
  if (a > 0 && b > 0) return std::exp(std::log(a) + p.t * (std::log(b) - std::log(a)));
  return a + p.t * (b - a);
}

}  // namespace qacc::compare
