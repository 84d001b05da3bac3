#include "tools/sweep/accuracy_target.h"

#include <cstdlib>
#include <map>
#include <sstream>
#include <stdexcept>

namespace qacc {

bool AccuracyCondition::holds(double v) const {
  if (op == "<=") return v <= value;
  if (op == "<") return v < value;
  if (op == ">=") return v >= value;
  if (op == ">") return v > value;
  return v == value;
}

namespace {
const std::map<std::string, std::string>& columns() {
  static const std::map<std::string, std::string> c = {
      {"wrong", "wrong_percent"},        {"wrong_object", "wrong_object"},
      {"pinholes", "pinholes"},          {"spurious", "spurious"},
      {"psnr", "psnr_db"},               {"ssim", "ssim"},
      {"hausdorff", "silhouette_hausdorff_px"}, {"silhouette_mean", "silhouette_mean_px"},
      {"depth_max", "depth_max_z24"},    {"depth_mean", "depth_mean_z24"}};
  return c;
}

double number(const nlohmann::ordered_json& v) {
  if (v.is_number()) return v.get<double>();
  if (v.is_string()) {
    const std::string s = v.get<std::string>();
    if (s == "inf") return 1e300;
    if (s == "-inf") return -1e300;
  }
  return std::nan("");
}
}  // namespace

bool AccuracyTarget::meets(const nlohmann::ordered_json& row) const {
  if (row.value("status", std::string("ok")) != "ok") return false;
  for (const auto& c : conditions) {
    if (!row.contains(c.column)) return false;
    const double v = number(row[c.column]);
    if (v != v || !c.holds(v)) return false;
  }
  return true;
}

AccuracyTarget parseAccuracyTarget(const std::string& text) {
  AccuracyTarget t;
  t.text = text;
  std::stringstream ss(text);
  std::string item;
  while (std::getline(ss, item, ',')) {
    std::string s;
    for (char ch : item)
      if (ch != ' ') s += ch;
    if (s.empty()) continue;
    const auto pos = s.find_first_of("<>=");
    if (pos == std::string::npos || pos == 0)
      throw std::invalid_argument("--target: '" + item + "' is not NAME OP VALUE (e.g. wrong<=0.1%)");
    AccuracyCondition c;
    c.name = s.substr(0, pos);
    std::size_t vpos = pos + 1;
    if (vpos < s.size() && s[vpos] == '=') ++vpos;
    c.op = s.substr(pos, vpos - pos);
    if (c.op == "=>" || c.op == "=<" || c.op == "==") c.op = "=";
    std::string v = s.substr(vpos);
    const auto col = columns().find(c.name);
    if (col == columns().end()) {
      std::string names;
      for (const auto& [k, _] : columns()) names += (names.empty() ? "" : ", ") + k;
      throw std::invalid_argument("--target: unknown measure '" + c.name + "' (known: " + names + ")");
    }
    c.column = col->second;
    if (!v.empty() && v.back() == '%') {
      if (c.name != "wrong") throw std::invalid_argument("--target: '%' applies to wrong only: '" + item + "'");
      v.pop_back();
    }
    char* end = nullptr;
    c.value = v.empty() ? 0 : std::strtod(v.c_str(), &end);
    if (v.empty() || end != v.c_str() + v.size() || c.value != c.value)
      throw std::invalid_argument("--target: '" + item + "': '" + v + "' is not a number");
    t.conditions.push_back(c);
  }
  if (t.conditions.empty()) throw std::invalid_argument("--target: no condition given");
  return t;
}

}  // namespace qacc
