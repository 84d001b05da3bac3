#include "hw_model/datapath/reciprocal_sqrt.h"

#include <array>
#include <cmath>

namespace qacc {

namespace {

constexpr int P = ReciprocalSqrt::kPrecision, S = ReciprocalSqrt::kSeedBits;

// The seed ROM: entry i - 2^(S-2) covers m in [i, i+1) · 2^(2P+2-S), i in [2^(S-2), 2^S).
const std::array<std::int64_t, (1 << S)>& seedRom() {
  static const std::array<std::int64_t, (1 << S)> rom = [] {
    std::array<std::int64_t, (1 << S)> r{};
    for (int i = 1 << (S - 2); i < (1 << S); ++i) {
      const double mid = std::ldexp(i + 0.5, 2 * P + 2 - S);
      r[std::size_t(i)] = std::llround(std::ldexp(1.0, 2 * P + 1) / std::sqrt(mid));
    }
    return r;
  }();
  return rom;
}

int bitLength128(unsigned __int128 v) {
  const std::uint64_t hi = std::uint64_t(v >> 64), lo = std::uint64_t(v);
  if (hi) return 128 - __builtin_clzll(hi);
  return lo ? 64 - __builtin_clzll(lo) : 0;
}

}  // namespace

ReciprocalSqrt::Result ReciprocalSqrt::compute(unsigned __int128 L) {
  Result r;
  if (L == 0) return r;
  // Even shift s = 2k bringing the bit length of m to 2P+1 or 2P+2.
  int s = bitLength128(L) - (2 * P + 2);
  if (s & 1) ++s;
  const std::uint64_t m = std::uint64_t(s >= 0 ? (L >> s) : (L << -s));
  r.k = s / 2;
  const std::int64_t y0 = seedRom()[std::size_t(m >> (2 * P + 2 - S))];
  const unsigned __int128 three = (unsigned __int128)3 << (4 * P + 2);
  const unsigned __int128 my2 = (unsigned __int128)m * (unsigned __int128)(y0 * y0);
  const unsigned __int128 t = three - my2;  // > 0: m y0² is within a few % of 2^(4P+2)
  r.y = std::int64_t(((unsigned __int128)y0 * t) >> (4 * P + 3));
  return r;
}

}  // namespace qacc
