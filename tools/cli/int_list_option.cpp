#include "tools/cli/int_list_option.h"

#include <sstream>
#include <stdexcept>

namespace qacc {

std::vector<int> parseIntListOption(const std::string& text, const std::string& option, const std::string& what,
                                    int lo, int hi) {
  std::vector<int> out;
  std::stringstream ss(text);
  std::string item;
  while (std::getline(ss, item, ',')) {
    std::size_t pos = 0;
    int v = 0;
    try {
      v = std::stoi(item, &pos);
    } catch (...) {
      pos = 0;
    }
    if (item.empty() || pos != item.size() || v < lo || v > hi)
      throw std::invalid_argument(option + ": '" + item + "' is not " + what + " (an integer from " +
                                  std::to_string(lo) + " to " + std::to_string(hi) + ")");
    out.push_back(v);
  }
  if (out.empty()) throw std::invalid_argument(option + ": nothing given");
  return out;
}

}  // namespace qacc
