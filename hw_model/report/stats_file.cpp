#include "hw_model/report/stats_file.h"

#include <cmath>
#include <fstream>
#include <stdexcept>

namespace qacc {

nlohmann::ordered_json jsonNumber(double v) {
  if (std::isfinite(v)) {
    if (v == std::floor(v) && std::fabs(v) < 9e15) return (long long)v;  // counts stay integers
    return v;
  }
  return v > 0 ? "inf" : (v < 0 ? "-inf" : "nan");
}

double jsonNumberValue(const nlohmann::ordered_json& v) {
  if (v.is_number()) return v.get<double>();
  if (v.is_string()) {
    const std::string& s = v.get_ref<const std::string&>();
    if (s == "inf") return INFINITY;
    if (s == "-inf") return -INFINITY;
  }
  return std::nan("");
}

namespace {
void flatten(const nlohmann::ordered_json& j, const std::string& prefix, std::vector<std::string>& keys,
             std::vector<std::string>& values) {
  for (auto it = j.begin(); it != j.end(); ++it) {
    const std::string k = prefix.empty() ? it.key() : prefix + "." + it.key();
    if (it->is_object()) {
      flatten(*it, k, keys, values);
    } else if (it->is_array()) {
      for (std::size_t i = 0; i < it->size(); ++i) {
        const auto& u = (*it)[i];
        if (!u.is_object()) {
          keys.push_back(k + "." + std::to_string(i));
          values.push_back(u.is_string() ? u.get<std::string>() : u.dump());
          continue;
        }
        const std::string p = k + "." + (u.contains("name") ? u["name"].get<std::string>() : std::to_string(i));
        for (auto f = u.begin(); f != u.end(); ++f) {
          if (f.key() == "name") continue;
          keys.push_back(p + "." + f.key());
          values.push_back(f->is_string() ? f->get<std::string>() : f->dump());
        }
      }
    } else {
      keys.push_back(k);
      values.push_back(it->is_string() ? it->get<std::string>() : it->dump());
    }
  }
}
}  // namespace

void flattenJson(const nlohmann::ordered_json& j, std::vector<std::string>& keys, std::vector<std::string>& values) {
  flatten(j, "", keys, values);
}

std::string jsonToCsvRow(const nlohmann::ordered_json& j) {
  std::vector<std::string> keys, values;
  flattenJson(j, keys, values);
  std::string a, b;
  for (std::size_t i = 0; i < keys.size(); ++i) {
    a += (i ? "," : "") + keys[i];
    b += (i ? "," : "") + values[i];
  }
  return a + "\n" + b + "\n";
}

void writeStatsFiles(const std::string& path, const nlohmann::ordered_json& j) {
  std::ofstream out(path);
  if (!out) throw std::invalid_argument(path + ": cannot write statistics");
  out << j.dump(2) << "\n";
  std::string csv = path;
  const auto dot = csv.find_last_of('.');
  const auto slash = csv.find_last_of('/');
  if (dot != std::string::npos && (slash == std::string::npos || dot > slash)) csv.resize(dot);
  csv += ".csv";
  std::ofstream c(csv);
  if (!c) throw std::invalid_argument(csv + ": cannot write statistics");
  c << jsonToCsvRow(j);
  if (!out || !c) throw std::invalid_argument(path + ": cannot write statistics");
}

void writeResultRows(const std::string& out, const std::string& format, const nlohmann::ordered_json& rows) {
  std::string base = out;
  for (const char* ext : {".json", ".csv"})
    if (base.size() > 5 && base.compare(base.size() - std::string(ext).size(), std::string::npos, ext) == 0)
      base.resize(base.size() - std::string(ext).size());
  nlohmann::ordered_json j;
  j["format"] = format;
  j["rows"] = rows;
  std::ofstream js(base + ".json");
  js << j.dump(1) << "\n";
  std::ofstream csv(base + ".csv");
  std::vector<std::string> header;
  for (std::size_t r = 0; r < rows.size(); ++r) {
    std::vector<std::string> keys, values;
    flattenJson(rows[r], keys, values);
    if (r == 0) {
      header = keys;
      for (std::size_t i = 0; i < keys.size(); ++i) csv << (i ? "," : "") << keys[i];
      csv << "\n";
    }
    for (std::size_t i = 0; i < values.size(); ++i) csv << (i ? "," : "") << values[i];
    csv << "\n";
  }
  if (!js || !csv) throw std::invalid_argument(base + ".json/.csv: cannot write");
}

}  // namespace qacc
