#include "tools/compare/equal_error.h"

#include <cmath>
#include <cstdio>
#include <string>

#include "tools/compare/number_format.h"

namespace qacc::compare {

ErrorScale errorScale(const MetricDef& d) {
  const std::string k = d.key;
  if (k == "psnr_db") return ErrorScale::Linear;
  if (k == "ssim") return ErrorScale::OneMinusLog;
  return ErrorScale::Log;
}

EqualErrorPoint equalErrorOf(const MetricDef& d, const Row& hw, const std::vector<Row>& facets) {
  std::vector<MeasuredError> m;
  for (const auto& r : facets) m.push_back({double(r.primitives), d.get(r.m)});
  return equalErrorPoint(m, d.get(hw.m), d.higher_better, errorScale(d));
}

double rowValueAt(const EqualErrorPoint& p, const std::vector<Row>& facets, double (*get)(const Row&)) {
  std::vector<double> v;
  for (const auto& r : facets) {
    const double x = get(r);
    v.push_back(x > 0 ? x : NAN);
  }
  return atPoint(p, v);
}

nlohmann::json equalErrorTable(const Row& hw, const std::vector<Row>& facets) {
  nlohmann::json jEqual = nlohmann::json::array();
  std::printf("\nequal error: smallest tessellation that reaches the accelerator (%zu quadrics, %llu cycles, "
              "%.1f ms host), interpolated between measured settings (at most one step beyond the finest)\n",
              hw.primitives, (unsigned long long)hw.cycles, hw.host_ms);
  std::printf("%-24s %10s %-22s %11s %9s %12s %9s %9s  %s\n", "metric", "hw", "status", "triangles", "tri/quad",
              "facet_cyc", "cyc_ratio", "draw_ms", "between settings");
  for (const auto& d : metricDefs()) {
    const double hv = d.get(hw.m);
    const EqualErrorPoint p = equalErrorOf(d, hw, facets);
    nlohmann::json j;
    j["metric"] = d.key;
    j["hw"] = jnum(hv);
    j["status"] = equalErrorStatusName(p.status);
    j["reached"] = p.status == EqualErrorStatus::AtCoarsest || p.status == EqualErrorStatus::Interpolated;
    const Row& finest = facets[p.finest];
    j["finest_setting"] = finest.setting();
    j["finest_triangles"] = finest.primitives;
    j["finest_facets"] = jnum(d.get(finest.m));
    j["quadric_cycles"] = hw.cycles;
    j["hw_host_ms"] = hw.host_ms;
    if (!p.found()) {
      std::printf("%-24s %10s %-22s (finest measured: %s, %zu triangles, %s)\n", d.label, fmt(hv, 4).c_str(),
                  "not reached", finest.setting().c_str(), finest.primitives, fmt(d.get(finest.m), 4).c_str());
      jEqual.push_back(j);
      continue;
    }
    const double cycles = rowValueAt(p, facets, [](const Row& r) { return double(r.cycles); });
    const double draw = rowValueAt(p, facets, [](const Row& r) { return r.draw_ms; });
    const double ratio = hw.cycles ? cycles / double(hw.cycles) : NAN;
    const std::string between = p.lo == p.hi ? facets[p.lo].setting() + " (coarsest measured)"
                                             : facets[p.lo].setting() + " .. " + facets[p.hi].setting() +
                                                   (p.status == EqualErrorStatus::Extrapolated ? " (+1 step)" : "");
    std::printf("%-24s %10s %-22s %11.0f %9.1f %12s %9s %9s  %s\n", d.label, fmt(hv, 4).c_str(),
                equalErrorStatusName(p.status), p.cost, p.cost / double(hw.primitives), fmt(cycles, 0).c_str(),
                fmt(ratio, 2).c_str(), fmt(draw, 1).c_str(), between.c_str());
    j["triangles"] = jnum(p.cost);
    j["facet_cycles"] = jnum(cycles);
    j["cycle_ratio"] = jnum(ratio);
    j["facets_draw_ms"] = jnum(draw);
    j["between"] = {facets[p.lo].setting(), facets[p.hi].setting()};
    j["between_rows"] = {p.lo, p.hi};  // indices into the facet rows (rows[1 + i] of the report)
    j["t"] = p.t;
    jEqual.push_back(j);
  }
  return jEqual;
}

}  // namespace qacc::compare
