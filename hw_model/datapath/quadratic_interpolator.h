// QuadraticInterpolator: P(u, v) = A u² + B uv + C v² + D u + E v + F over integer pixel
// offsets (u, v) from the primitive's local origin, with integer coefficients (the real
// coefficients quantised by the setup unit with `frac` extra fraction bits).
//
// Hardware (Pixel-Planes style, digest §1): along a span, forward differences
//   P(u+1) = P(u) + d,   d(u+1) = d(u) + 2A,   d(u) = A(2u+1) + Bv + D
// — two additions per pixel, exact in integer arithmetic, so the value after any number
// of steps equals direct evaluation (tests check it). The accumulator has `accBits`
// bits; a value outside it is an overflow (counted; the output saturates). The datapath
// output is P >> frac (floor), i.e. the integer part in the datapath's own scale.
#pragma once
#include "hw_model/datapath/fixed_point.h"

namespace qacc {

struct QuadraticCoefficients {
  i128 A = 0, B = 0, C = 0, D = 0, E = 0, F = 0;
};

class QuadraticInterpolator {
 public:
  QuadraticInterpolator() = default;
  QuadraticInterpolator(const QuadraticCoefficients& k, int frac, int accBits) : k_(k), frac_(frac), acc_(accBits) {}

  // Direct evaluation (the span-start value the traversal loads, or a check).
  i128 direct(long long u, long long v) const {
    const i128 U = u, V = v;
    return k_.A * U * U + k_.B * U * V + k_.C * V * V + k_.D * U + k_.E * V + k_.F;
  }
  // Starts a span at (u, v).
  void start(long long u, long long v) {
    value_ = direct(u, v);
    step_ = k_.A * (2 * i128(u) + 1) + k_.B * i128(v) + k_.D;
  }
  // Moves one pixel right.
  void stepRight() {
    value_ += step_;
    step_ += 2 * k_.A;
  }
  i128 raw() const { return value_; }
  // Output of the datapath: the accumulator narrowed to accBits (counted), then >> frac.
  i128 output(OverflowMode mode, OverflowCounter& ovf) const {
    return fitWidth(value_, acc_, mode, ovf) >> frac_;
  }
  const QuadraticCoefficients& coefficients() const { return k_; }
  int frac() const { return frac_; }

 private:
  QuadraticCoefficients k_;
  int frac_ = 0;
  int acc_ = 100;
  i128 value_ = 0, step_ = 0;
};

}  // namespace qacc
