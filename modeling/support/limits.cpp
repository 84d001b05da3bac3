#include "modeling/support/limits.h"

#include <limits>

namespace qacc {

std::string Limits::exceeded(const std::string& what, std::size_t needed, const char* unit, std::size_t limit,
                             const char* option) {
  return what + " needs " + std::to_string(needed) + " " + unit + ", above the limit of " + std::to_string(limit) +
         " (raise it with --" + option + ")";
}

std::size_t Limits::clipWork(std::size_t planes) {
  constexpr std::size_t kMax = std::numeric_limits<std::size_t>::max();
  if (planes > (std::size_t(1) << 20)) return kMax;  // (n + 6)^4 / 6 > 2^64
  const unsigned __int128 m = planes + 6;
  const unsigned __int128 tests = m * (m - 1) * (m - 2) / 6 * m - 120;
  return tests > kMax ? kMax : std::size_t(tests);
}

std::size_t Limits::addSaturated(std::size_t a, std::size_t b) {
  return a > std::numeric_limits<std::size_t>::max() - b ? std::numeric_limits<std::size_t>::max() : a + b;
}

}  // namespace qacc
