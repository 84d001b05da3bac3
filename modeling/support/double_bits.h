// A double's IEEE 754 bit pattern and back (what C++20's std::bit_cast does; the project is
// C++17). Non-negative doubles are ordered as their patterns, so walking or bisecting the
// patterns visits every double between two values in order.
#pragma once
#include <cstdint>
#include <cstring>

namespace qacc {

inline std::uint64_t doubleBits(double v) {
  std::uint64_t b;
  std::memcpy(&b, &v, sizeof b);
  return b;
}

inline double doubleFromBits(std::uint64_t b) {
  double v;
  std::memcpy(&v, &b, sizeof v);
  return v;
}

}  // namespace qacc
