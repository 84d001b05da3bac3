#include "hw_model/datapath/sqrt_extractor.h"

#include <cmath>

namespace qacc {

std::uint64_t SqrtExtractor::recurrence(unsigned __int128 n, int inputBits, int radix) {
  // Partial remainder r and partial root q. Each radix-2 step brings down two operand
  // bits and decides one root bit: trial = 4 r + next2 − (4 q + 1). A radix-4 step
  // decides two bits at once by selecting the largest digit d in {0..3} with
  // (4 q + d) d <= 4 r' (r' the remainder after bringing down 4 operand bits), which is
  // the same digit sequence taken two at a time.
  const int bits = (inputBits + 1) & ~1;
  unsigned __int128 r = 0, q = 0;
  if (radix == 4) {
    const int steps = (bits + 3) / 4;
    for (int s = steps - 1; s >= 0; --s) {
      const unsigned __int128 next4 = (n >> (4 * s)) & 0xF;
      r = (r << 4) | next4;
      unsigned d = 3;
      for (; d > 0; --d) {
        const unsigned __int128 t = ((q << 2) * 2 + d) * d;  // (2·4q + d)·d = (4q+d)² − 16q²
        if (t <= r) break;
      }
      r -= ((q << 2) * 2 + d) * d;
      q = (q << 2) | d;
    }
  } else {
    const int steps = bits / 2;
    for (int s = steps - 1; s >= 0; --s) {
      const unsigned __int128 next2 = (n >> (2 * s)) & 0x3;
      r = (r << 2) | next2;
      const unsigned __int128 t = (q << 2) | 1;
      if (r >= t) {
        r -= t;
        q = (q << 1) | 1;
      } else {
        q <<= 1;
      }
    }
  }
  return std::uint64_t(q);
}

std::uint64_t SqrtExtractor::computeWide(unsigned __int128 n) {
  // Operands are below 2^124 (delta_bits <= 80 in any configuration), so x² cannot wrap.
  unsigned __int128 x = (unsigned __int128)std::sqrt((long double)n);
  while (x * x > n) --x;
  while ((x + 1) * (x + 1) <= n) ++x;
  return std::uint64_t(x);
}

}  // namespace qacc
