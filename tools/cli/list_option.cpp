#include "tools/cli/list_option.h"

#include <cmath>
#include <functional>
#include <sstream>
#include <stdexcept>

namespace qacc {

namespace {

// Splits `text` at commas and converts every item with `parse` (false: refused).
template <typename T>
std::vector<T> parseList(const std::string& text, const std::string& option, const std::string& refusal,
                         const std::function<bool(const std::string&, T&)>& parse) {
  std::vector<T> out;
  std::stringstream ss(text);
  std::string item;
  while (std::getline(ss, item, ',')) {
    T v{};
    if (item.empty() || !parse(item, v)) throw std::invalid_argument(option + ": '" + item + "' is not " + refusal);
    out.push_back(v);
  }
  if (!text.empty() && text.back() == ',')  // getline drops the empty last item
    throw std::invalid_argument(option + ": '' is not " + refusal);
  if (out.empty()) throw std::invalid_argument(option + ": nothing given");
  return out;
}

std::string shortNumber(double v) {
  std::ostringstream s;
  s << v;
  return s.str();
}

}  // namespace

std::vector<int> parseIntListOption(const std::string& text, const std::string& option, const std::string& what,
                                    int lo, int hi) {
  return parseList<int>(text, option,
                        what + " (an integer from " + std::to_string(lo) + " to " + std::to_string(hi) + ")",
                        [&](const std::string& item, int& v) {
                          std::size_t pos = 0;
                          try {
                            v = std::stoi(item, &pos);
                          } catch (...) {
                            return false;
                          }
                          return pos == item.size() && v >= lo && v <= hi;
                        });
}

std::vector<double> parseDoubleListOption(const std::string& text, const std::string& option, const std::string& what,
                                          double lo, double hi) {
  return parseList<double>(
      text, option, what + " (a number from " + shortNumber(lo) + " to " + shortNumber(hi) + ")",
      [&](const std::string& item, double& v) {
        if (item.find_first_not_of("0123456789.eE+-") != std::string::npos) return false;  // no nan, inf, hex
        std::size_t pos = 0;
        try {
          v = std::stod(item, &pos);
        } catch (...) {
          return false;
        }
        return pos == item.size() && std::isfinite(v) && v >= lo && v <= hi;
      });
}

}  // namespace qacc
