// The reference the division tests compare with: num / den (den != 0) by 128-bit integer
// division of the magnitudes, rounded with r (Truncate: toward zero; Nearest: ties away from
// zero; NearestEven: ties to even), written apart from divRound so that the tests do not
// check the datapath's division against itself.
#pragma once
#include "hw_model/datapath/fixed_point.h"

namespace qacc::test {

inline i128 exactDivRound(i128 num, i128 den, Rounding r) {
  if (den < 0) {
    num = -num;
    den = -den;
  }
  const bool neg = num < 0;
  const i128 n = neg ? -num : num;
  i128 q = n / den;
  const i128 rem = n % den;
  if (r != Rounding::Truncate && (2 * rem > den || (2 * rem == den && (r == Rounding::Nearest || (q & 1))))) ++q;
  return neg ? -q : q;
}

}  // namespace qacc::test
