#include "tools/sweep/sweep_results.h"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <map>
#include <set>
#include <sstream>
#include <stdexcept>

#include "hw_model/report/stats_file.h"
#include "tools/sweep/accuracy_target.h"
#include "tools/sweep/pareto_front.h"

namespace qacc {

namespace fs = std::filesystem;

bool isHostColumn(const std::string& c) {
  return c == "host_seconds" || c == "reference_rendered" || c == "accuracy_reused" || c == "datapath_reused";
}

namespace {

double num(const nlohmann::ordered_json& row, const std::string& k) {
  return row.contains(k) ? jsonNumberValue(row[k]) : std::nan("");
}

bool ok(const nlohmann::ordered_json& row) { return row.value("status", std::string()) == "ok"; }

// The front of (cost, error) pairs as [{idName: key, costName: cost, "wrong_percent": error}].
nlohmann::ordered_json frontJson(const std::vector<std::pair<double, double>>& costError,
                                 const std::vector<std::size_t>& keys, const char* idName, const char* costName) {
  nlohmann::ordered_json a = nlohmann::ordered_json::array();
  for (std::size_t i : paretoFront(costError))
    a.push_back({{idName, keys[i]}, {costName, costError[i].first}, {"wrong_percent", costError[i].second}});
  return a;
}

// Aggregated per point over the scenes.
struct PointAgg {
  bool complete = true;
  std::size_t seen = 0;
  double wrong = 0, pinholes = 0, cycles = 0, gates = std::nan(""), psnr = INFINITY;
  std::string label;
  bool meets = true;
};

}  // namespace

nlohmann::ordered_json sweepFronts(const SweepResults& r) {
  nlohmann::ordered_json out;
  AccuracyTarget target;
  if (!r.target.empty()) target = parseAccuracyTarget(r.target);
  // Per scene.
  std::map<std::string, std::vector<const nlohmann::ordered_json*>> byScene;
  std::vector<std::string> sceneOrder;
  for (const auto& row : r.rows) {
    const std::string s = row.value("scene", std::string());
    if (!byScene.count(s)) sceneOrder.push_back(s);
    byScene[s].push_back(&row);
  }
  nlohmann::ordered_json scenes = nlohmann::ordered_json::object();
  for (const std::string& s : sceneOrder) {
    std::vector<std::pair<double, double>> eg, ec;
    std::vector<std::size_t> items;
    for (const auto* row : byScene[s]) {
      if (!ok(*row)) continue;
      items.push_back((*row)["item"].get<std::size_t>());
      eg.push_back({num(*row, "gates_kge"), num(*row, "wrong_percent")});
      ec.push_back({num(*row, "cycles"), num(*row, "wrong_percent")});
    }
    scenes[s] = {{"error_vs_gates", frontJson(eg, items, "item", "gates_kge")},
                 {"error_vs_cycles", frontJson(ec, items, "item", "cycles")}};
  }
  out["scenes"] = scenes;
  // All scenes, per point.
  std::map<std::size_t, PointAgg> agg;
  for (const auto& row : r.rows) {
    PointAgg& a = agg[row["point"].get<std::size_t>()];
    a.label = row.value("label", std::string());
    ++a.seen;
    if (!ok(row)) {
      a.complete = false;
      a.meets = false;
      continue;
    }
    a.wrong = std::max(a.wrong, num(row, "wrong_percent"));
    a.pinholes += num(row, "pinholes");
    a.cycles += num(row, "cycles");
    // The lowest PSNR over the scenes; one scene without it makes the point's unknown (NaN).
    a.psnr = foldLowestPsnr(a.psnr, row);
    a.gates = num(row, "gates_kge");
    if (!target.empty() && !target.meets(row)) a.meets = false;
  }
  std::vector<std::size_t> pts;
  std::vector<std::pair<double, double>> eg, ec;
  for (const auto& [p, a] : agg) {
    if (!a.complete || a.seen != r.scenes) continue;
    pts.push_back(p);
    eg.push_back({a.gates, a.wrong});
    ec.push_back({a.cycles, a.wrong});
  }
  out["all"] = {{"error_vs_gates", frontJson(eg, pts, "point", "gates_kge")},
                {"error_vs_cycles", frontJson(ec, pts, "point", "cycles")}};
  if (!target.empty()) {
    long best = -1;
    for (std::size_t i = 0; i < pts.size(); ++i) {
      const PointAgg& a = agg[pts[i]];
      if (!a.meets) continue;
      if (best < 0) {
        best = long(i);
        continue;
      }
      const PointAgg& b = agg[pts[std::size_t(best)]];
      if (a.gates < b.gates || (a.gates == b.gates && a.cycles < b.cycles)) best = long(i);
    }
    nlohmann::ordered_json ans;
    ans["target"] = r.target;
    if (best >= 0) {
      const std::size_t p = pts[std::size_t(best)];
      ans["point"] = p;
      ans["label"] = agg[p].label;
      ans["gates_kge"] = agg[p].gates;
      ans["worst_wrong_percent"] = agg[p].wrong;
      // The target may bound classes of wrong pixels only; the colour error of the same point
      // is given beside them: its lowest PSNR over the scenes, written as the rows' PSNR is
      // ("inf": every image identical; "nan": a scene without it).
      ans["worst_psnr_db"] = jsonNumber(agg[p].psnr);
      ans["cycles"] = agg[p].cycles;
      nlohmann::ordered_json cfg = nlohmann::ordered_json::object();
      for (const auto& row : r.rows)
        if (row["point"].get<std::size_t>() == p) {
          for (auto it = row.begin(); it != row.end(); ++it)
            if (it.key().rfind("config.", 0) == 0) cfg[it.key().substr(7)] = it.value();
          break;
        }
      ans["configuration"] = cfg;
    } else {
      ans["point"] = nullptr;
      ans["note"] = "no point of the sweep meets the target on every scene";
    }
    out["answer"] = ans;
  }
  return out;
}

namespace {

std::string csvField(const nlohmann::ordered_json& v) {
  std::string s = v.is_string() ? v.get<std::string>() : (v.is_null() ? "" : v.dump());
  if (s.find_first_of(",\"\n") != std::string::npos) {
    std::string q = "\"";
    for (char c : s) q += c == '"' ? std::string("\"\"") : std::string(1, c);
    return q + "\"";
  }
  return s;
}

void writeFile(const fs::path& p, const std::string& text) {
  std::ofstream out(p);
  out << text;
  if (!out) throw std::invalid_argument(p.string() + ": cannot write");
}

}  // namespace

void writeSweepResults(const std::string& dir, const SweepResults& r) {
  fs::create_directories(dir);
  nlohmann::ordered_json j;
  j["format"] = "qacc-sweep-results/1";
  j["spec_file"] = r.spec_file;
  j["spec_hash"] = r.spec_hash;
  j["shard"] = r.shard;
  j["points"] = r.points;
  j["scenes"] = r.scenes;
  j["target"] = r.target;
  j["spec"] = r.spec;
  j["rows"] = r.rows;
  j["fronts"] = sweepFronts(r);
  writeFile(fs::path(dir) / "results.json", j.dump(1) + "\n");
  // CSV: the union of the columns in first-seen order.
  std::vector<std::string> cols;
  std::set<std::string> seen;
  for (const auto& row : r.rows)
    for (auto it = row.begin(); it != row.end(); ++it)
      if (seen.insert(it.key()).second) cols.push_back(it.key());
  std::string csv;
  for (std::size_t i = 0; i < cols.size(); ++i) csv += (i ? "," : "") + cols[i];
  csv += "\n";
  for (const auto& row : r.rows) {
    for (std::size_t i = 0; i < cols.size(); ++i) csv += (i ? "," : "") + (row.contains(cols[i]) ? csvField(row[cols[i]]) : "");
    csv += "\n";
  }
  writeFile(fs::path(dir) / "results.csv", csv);
  std::string fc = "scope,front,id,cost,wrong_percent\n";
  const auto fr = j["fronts"];
  auto addFront = [&](const std::string& scope, const nlohmann::ordered_json& f, const char* id) {
    for (const char* name : {"error_vs_gates", "error_vs_cycles"})
      for (const auto& e : f[name]) {
        const std::string costKey = std::string(name) == "error_vs_gates" ? "gates_kge" : "cycles";
        fc += csvField(scope) + "," + name + "," + e[id].dump() + "," + e[costKey].dump() + "," +
              e["wrong_percent"].dump() + "\n";
      }
  };
  for (auto it = fr["scenes"].begin(); it != fr["scenes"].end(); ++it) addFront(it.key(), it.value(), "item");
  addFront("all", fr["all"], "point");
  writeFile(fs::path(dir) / "fronts.csv", fc);
}

SweepResults readSweepResults(const std::string& dir) {
  const fs::path p = fs::path(dir) / "results.json";
  std::ifstream in(p);
  if (!in) throw std::invalid_argument(p.string() + ": cannot open (not a sweep output directory?)");
  std::stringstream ss;
  ss << in.rdbuf();
  nlohmann::ordered_json j;
  try {
    j = nlohmann::ordered_json::parse(ss.str());
  } catch (const std::exception& e) {
    throw std::invalid_argument(p.string() + ": JSON syntax error: " + e.what());
  }
  if (!j.is_object() || j.value("format", std::string()) != "qacc-sweep-results/1")
    throw std::invalid_argument(p.string() + ": /format: expected \"qacc-sweep-results/1\"");
  SweepResults r;
  try {
    r.spec = j.at("spec");
    r.spec_file = j.at("spec_file").get<std::string>();
    r.spec_hash = j.at("spec_hash").get<std::string>();
    r.target = j.at("target").get<std::string>();
    r.points = j.at("points").get<std::size_t>();
    r.scenes = j.at("scenes").get<std::size_t>();
    r.shard = j.at("shard").get<std::string>();
    for (const auto& row : j.at("rows")) {
      if (!row.is_object() || !row.contains("item") || !row["item"].is_number_unsigned())
        throw std::invalid_argument("/rows: a row without an item number");
      r.rows.push_back(row);
    }
  } catch (const std::exception& e) {
    throw std::invalid_argument(p.string() + ": " + e.what());
  }
  return r;
}

SweepResults mergeSweepResults(const std::vector<SweepResults>& parts, const std::vector<std::string>& names) {
  if (parts.empty()) throw std::invalid_argument("--merge: no directory given");
  SweepResults m = parts[0];
  m.shard = "";
  m.rows.clear();
  std::map<std::size_t, nlohmann::ordered_json> rows;
  for (std::size_t i = 0; i < parts.size(); ++i) {
    if (parts[i].spec_hash != parts[0].spec_hash)
      throw std::invalid_argument(names[i] + ": results of another spec (hash " + parts[i].spec_hash + ", " + names[0] +
                                  " has " + parts[0].spec_hash + ")");
    for (const auto& row : parts[i].rows) {
      const std::size_t item = row["item"].get<std::size_t>();
      if (!rows.emplace(item, row).second)
        throw std::invalid_argument(names[i] + ": item " + std::to_string(item) + " is also in another directory");
    }
  }
  const std::size_t total = m.points * m.scenes;
  if (rows.size() != total) {
    std::string missing;
    int n = 0;
    for (std::size_t k = 0; k < total && n < 8; ++k)
      if (!rows.count(k)) missing += (n++ ? ", " : "") + std::to_string(k);
    throw std::invalid_argument("--merge: " + std::to_string(total - rows.size()) + " of " + std::to_string(total) +
                                " items are missing (first: " + missing + "); is a shard missing?");
  }
  for (auto& [k, row] : rows) m.rows.push_back(row);
  return m;
}

double foldLowestPsnr(double lowest, const nlohmann::ordered_json& row) {
  const double psnr = num(row, "psnr_db");
  return std::isnan(psnr) || std::isnan(lowest) ? std::nan("") : std::min(lowest, psnr);
}

std::string lowestPsnrText(double psnr) {
  if (std::isnan(psnr)) return "PSNR not measured";
  if (psnr == INFINITY) return "every image identical to the reference";
  char t[64];
  std::snprintf(t, sizeof t, "lowest PSNR %.1f dB", psnr);
  return t;
}

}  // namespace qacc
