#include "hw_model/datapath/fixed_point.h"

#include <stdexcept>

namespace qacc {

Rounding roundingFromString(const std::string& s) {
  if (s == "truncate") return Rounding::Truncate;
  if (s == "nearest") return Rounding::Nearest;
  if (s == "nearest_even") return Rounding::NearestEven;
  throw std::invalid_argument("unknown rounding mode '" + s + "' (truncate|nearest|nearest_even)");
}

OverflowMode overflowFromString(const std::string& s) {
  if (s == "saturate") return OverflowMode::Saturate;
  if (s == "wrap") return OverflowMode::Wrap;
  throw std::invalid_argument("unknown overflow mode '" + s + "' (saturate|wrap)");
}

std::string toString(Rounding r) {
  switch (r) {
    case Rounding::Truncate: return "truncate";
    case Rounding::Nearest: return "nearest";
    case Rounding::NearestEven: return "nearest_even";
  }
  return "?";
}

std::string toString(OverflowMode m) { return m == OverflowMode::Saturate ? "saturate" : "wrap"; }

}  // namespace qacc
