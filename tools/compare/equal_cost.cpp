#include "tools/compare/equal_cost.h"

#include <cmath>
#include <cstdio>
#include <functional>
#include <string>

#include "tools/compare/image_metrics.h"
#include "tools/compare/number_format.h"

namespace qacc::compare {

namespace {

// Nearest row (log scale) to a target value among facet rows; -1 if none.
int nearestLog(const std::vector<Row>& rows, double target, const std::function<double(const Row&)>& key) {
  int best = -1;
  double bd = 1e300;
  for (std::size_t i = 0; i < rows.size(); ++i) {
    const double k = key(rows[i]);
    if (!(k > 0) || !(target > 0)) continue;
    const double d = std::abs(std::log(k / target));
    if (d < bd) {
      bd = d;
      best = int(i);
    }
  }
  return best;
}

}  // namespace

nlohmann::json equalCostTable(const Row& hw, const std::vector<Row>& facets) {
  nlohmann::json jCost = nlohmann::json::object();
  std::printf("\nequal cost: facets nearest to the accelerator's budget (log scale); host time is hw's whole frame "
              "against llvmpipe's draw alone (context, upload and tessellation apart)\n");
  struct Budget {
    const char* key;
    const char* label;
    double target;
    std::function<double(const Row&)> get;
  };
  const std::vector<Budget> budgets = {
      {"primitives", "same primitive count", double(hw.primitives), [](const Row& r) { return double(r.primitives); }},
      {"cycles", "same modeled cycles", double(hw.cycles), [](const Row& r) { return double(r.cycles); }},
      // The draw alone: OSMesa's colour pass (draw + glFinish, after a warm-up draw), not the
      // context creation, the upload or the tessellation, which are reported apart.
      {"draw_ms", "same host draw time", hw.host_ms, [](const Row& r) { return r.draw_ms; }},
  };
  for (const auto& b : budgets) {
    const int i = nearestLog(facets, b.target, b.get);
    if (i < 0) {
      std::printf("  %-22s: not measured\n", b.label);
      continue;
    }
    const Row& r = facets[std::size_t(i)];
    std::printf("  %-22s: hw %s vs facets %s (%s): PSNR %s vs %s, SSIM %.4f vs %.4f, coverage %zu vs %zu px, "
                "Hausdorff %s vs %s px\n",
                b.label, fmt(b.target, 1).c_str(), r.setting().c_str(), fmt(b.get(r), 1).c_str(), fmt(hw.m.psnr, 2).c_str(),
                fmt(r.m.psnr, 2).c_str(), hw.m.ssim, r.m.ssim, std::size_t(hw.m.coverage()), std::size_t(r.m.coverage()),
                fmt(hw.m.hausdorff, 2).c_str(), fmt(r.m.hausdorff, 2).c_str());
    nlohmann::json j;
    j["hw_budget"] = jnum(b.target);
    j["setting"] = r.setting();
    j["level"] = r.level;
    j["tolerance_px"] = r.tolerance_px;
    j["facets_context_ms"] = r.context_ms;
    j["facets_upload_ms"] = r.upload_ms;
    j["facets_draw_ms"] = r.draw_ms;
    j["facets_budget"] = jnum(b.get(r));
    for (const auto& d : metricDefs()) {
      j["hw_" + std::string(d.key)] = jnum(d.get(hw.m));
      j["facets_" + std::string(d.key)] = jnum(d.get(r.m));
    }
    jCost[b.key] = j;
  }

  return jCost;
}

}  // namespace qacc::compare
