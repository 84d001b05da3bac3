#include "modeling/support/limits.h"

namespace qacc {

std::string Limits::exceeded(const std::string& what, std::size_t needed, const char* unit, std::size_t limit,
                             const char* option) {
  return what + " needs " + std::to_string(needed) + " " + unit + ", above the limit of " + std::to_string(limit) +
         " (raise it with --" + option + ")";
}

}  // namespace qacc
