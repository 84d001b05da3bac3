// LinearInterpolator: L(u, v) = A u + B v + C over integer pixel offsets, integer
// coefficients with `frac` extra fraction bits (quantised by setup). One addition per
// pixel step, exact; the output is the accumulator >> frac (floor), or the raw
// accumulator where a consumer wants the full precision (clip-plane sign tests).
#pragma once
#include "hw_model/datapath/fixed_point.h"

namespace qacc {

struct LinearCoefficients {
  i128 A = 0, B = 0, C = 0;
};

class LinearInterpolator {
 public:
  LinearInterpolator() = default;
  explicit LinearInterpolator(const LinearCoefficients& k) : k_(k) {}
  i128 direct(long long u, long long v) const { return k_.A * i128(u) + k_.B * i128(v) + k_.C; }
  void start(long long u, long long v) { value_ = direct(u, v); }
  void stepRight() { value_ += k_.A; }
  i128 raw() const { return value_; }
  const LinearCoefficients& coefficients() const { return k_; }

 private:
  LinearCoefficients k_;
  i128 value_ = 0;
};

}  // namespace qacc
