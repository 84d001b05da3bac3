#include "tools/sweep/autosize.h"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <numeric>
#include <stdexcept>

#include "hw_model/report/cost_model.h"
#include "tools/sweep/sweep_results.h"

namespace qacc {

namespace {

struct Search {
  const AutosizeOptions& o;
  SweepEvaluator& ev;
  std::size_t evaluations = 0;
  std::vector<std::vector<int>> failed;  // width vectors that failed the target

  // A configuration with `keys` set to `v`; false when refused at load.
  bool make(const std::vector<std::string>& keys, const std::vector<int>& v, HwConfig& c) const {
    c = o.base;
    try {
      for (std::size_t i = 0; i < keys.size(); ++i) setHwConfigKey(c, keys[i], v[i], "autosize");
      checkHwConfig(c, "autosize");
    } catch (const std::invalid_argument&) {
      return false;
    }
    return true;
  }
  // Renders on every scene; true when every scene meets the target.
  // `worst` and `psnr`, when given, receive the worst scene's wrong pixels and the lowest PSNR
  // (NaN when a scene lacks it) over the scenes rendered.
  bool meets(const HwConfig& c, double* worst, double* psnr = nullptr) {
    ++evaluations;
    double w = 0, p = INFINITY;
    bool ok = true;
    for (const std::string& s : o.scenes) {
      const nlohmann::ordered_json row = ev.evaluate(c, o.knobs, s);
      w = std::max(w, row["wrong_percent"].get<double>());
      p = foldLowestPsnr(p, row);
      if (!o.target.meets(row)) {
        ok = false;
        break;  // one failing scene decides
      }
    }
    if (worst) *worst = w;
    if (psnr) *psnr = p;
    return ok;
  }
};

std::vector<int> candidates(const AutosizeOptions& o, const std::string& key) {
  const auto it = o.values.find(key);
  std::vector<int> v;
  if (it != o.values.end()) {
    v = it->second;
  } else {
    const int b = hwConfigValue(o.base, key).get<int>();
    for (int x = b;; x -= o.step) {
      HwConfig scratch;
      try {
        setHwConfigKey(scratch, key, x, key);
      } catch (const std::invalid_argument&) {
        break;
      }
      v.push_back(x);
    }
  }
  std::sort(v.rbegin(), v.rend());
  v.erase(std::unique(v.begin(), v.end()), v.end());
  if (v.empty()) throw std::invalid_argument("autosize: no candidate value for " + key);
  return v;
}

}  // namespace

AutosizeResult autosize(const AutosizeOptions& o, SweepEvaluator& ev) {
  if (o.target.empty()) throw std::invalid_argument("autosize: --target is required");
  std::vector<std::string> keys = o.keys;
  if (keys.empty())
    for (const auto& k : hwConfigKeys())
      if (isHwWidthKey(k)) keys.push_back(k);
  for (const auto& k : keys)
    if (!isHwWidthKey(k)) throw std::invalid_argument("autosize: '" + k + "' is not a datapath width key");
  for (const auto& [k, _] : o.values)
    if (std::find(keys.begin(), keys.end(), k) == keys.end())
      throw std::invalid_argument("autosize: values given for '" + k + "', which is not searched (--keys)");
  Search s{o, ev, 0, {}};
  AutosizeResult r;
  r.base_gates_kge = CostModel::of(o.base).totalGe() / 1e3;
  // 1. Candidates, 2. bounds of each key alone.
  std::vector<std::vector<int>> cand;
  std::vector<int> baseValues;
  for (const auto& k : keys) baseValues.push_back(hwConfigValue(o.base, k).get<int>());
  for (std::size_t i = 0; i < keys.size(); ++i) {
    const std::vector<int> all = candidates(o, keys[i]);
    std::vector<int> kept;
    for (int v : all) {
      std::vector<int> vals = baseValues;
      vals[i] = v;
      HwConfig c;
      if (v > baseValues[i]) {
        kept.push_back(v);  // wider than the base: kept, never narrows the bound
        continue;
      }
      if (!s.make(keys, vals, c)) break;
      if (!s.meets(c, nullptr)) {
        s.failed.push_back(vals);
        break;
      }
      kept.push_back(v);
    }
    if (kept.empty()) kept.push_back(all.front());
    r.bound[keys[i]] = kept.back();
    cand.push_back(kept);
  }
  // 3. The grid in cost order.
  std::size_t total = 1;
  for (const auto& c : cand) {
    total *= c.size();
    if (total > o.max_grid)
      throw std::invalid_argument("autosize: the candidate grid has more than " + std::to_string(o.max_grid) +
                                  " configurations: search fewer --keys or use a larger --step");
  }
  struct Cand {
    double ge;
    int sum;
    std::vector<int> v;
  };
  std::vector<Cand> grid;
  grid.reserve(total);
  std::vector<int> v(keys.size());
  for (std::size_t n = 0; n < total; ++n) {
    std::size_t rest = n;
    for (std::size_t k = keys.size(); k-- > 0;) {
      v[k] = cand[k][rest % cand[k].size()];
      rest /= cand[k].size();
    }
    HwConfig c;
    if (!s.make(keys, v, c)) continue;
    grid.push_back({CostModel::of(c).totalGe(), std::accumulate(v.begin(), v.end(), 0), v});
  }
  r.grid = grid.size();
  std::sort(grid.begin(), grid.end(), [](const Cand& a, const Cand& b) {
    if (a.ge != b.ge) return a.ge < b.ge;
    if (a.sum != b.sum) return a.sum < b.sum;
    return a.v < b.v;
  });
  auto dominatedByFailure = [&](const std::vector<int>& x) {
    for (const auto& f : s.failed) {
      bool le = true;
      for (std::size_t k = 0; k < x.size() && le; ++k) le = x[k] <= f[k];
      if (le) return true;
    }
    return false;
  };
  for (const Cand& g : grid) {
    if (dominatedByFailure(g.v)) continue;
    HwConfig c;
    s.make(keys, g.v, c);
    double worst = 0, psnr = 0;
    const bool ok = s.meets(c, &worst, &psnr);
    if (o.verbose) {
      std::string d;
      for (std::size_t k = 0; k < keys.size(); ++k) d += (k ? " " : "") + keys[k] + "=" + std::to_string(g.v[k]);
      std::printf("  %.1f kGE %s: %s\n", g.ge / 1e3, d.c_str(), ok ? "meets the target" : "fails");
    }
    if (!ok) {
      s.failed.push_back(g.v);
      continue;
    }
    r.found = true;
    r.best = c;
    r.best.name = "autosize";
    r.gates_kge = g.ge / 1e3;
    r.worst_wrong_percent = worst;
    r.worst_psnr_db = psnr;
    break;
  }
  r.evaluations = s.evaluations;
  return r;
}

}  // namespace qacc
