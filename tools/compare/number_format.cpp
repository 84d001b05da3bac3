#include "tools/compare/number_format.h"

#include <cmath>
#include <cstdio>

namespace qacc::compare {

nlohmann::json jnum(double v) {
  if (std::isfinite(v)) return v;
  return v > 0 ? "inf" : (v < 0 ? "-inf" : "nan");
}

std::string sci(double v) {
  if (!std::isfinite(v)) return std::isnan(v) ? "n/a" : (v > 0 ? "inf" : "-inf");
  char b[32];
  std::snprintf(b, sizeof b, "%.2e", v);
  return b;
}

std::string fmt(double v, int prec) {
  if (std::isinf(v)) return v > 0 ? "inf" : "-inf";
  if (std::isnan(v)) return "n/a";
  char b[32];
  std::snprintf(b, sizeof b, "%.*f", prec, v);
  return b;
}

}  // namespace qacc::compare
