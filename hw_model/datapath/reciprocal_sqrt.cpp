#include "hw_model/datapath/reciprocal_sqrt.h"

#include <array>
#include <cmath>

namespace qacc {

const std::array<std::int64_t, (1 << ReciprocalSqrt::kSeedBits)> ReciprocalSqrt::kSeedRom = [] {
  constexpr int P = kPrecision, S = kSeedBits;
  std::array<std::int64_t, (1 << S)> r{};
  for (int i = 1 << (S - 2); i < (1 << S); ++i) {
    const double mid = std::ldexp(i + 0.5, 2 * P + 2 - S);
    r[std::size_t(i)] = std::llround(std::ldexp(1.0, 2 * P + 1) / std::sqrt(mid));
  }
  return r;
}();

}  // namespace qacc
