#include "tools/compare/equal_error.h"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <string>

#include "tools/compare/image_metrics.h"
#include "tools/compare/number_format.h"

namespace qacc::compare {

nlohmann::json equalErrorTable(const Row& hw, const std::vector<Row>& facets) {
  nlohmann::json jEqual = nlohmann::json::array();
  std::printf("\nequal error: smallest tessellation no worse than the accelerator (%zu quadrics, %.1f ms host, %llu cycles)\n",
              hw.primitives, hw.host_ms, (unsigned long long)hw.cycles);
  std::printf("%-24s %10s %10s %6s %9s %8s %11s %11s %8s\n", "metric", "hw", "facets", "level", "triangles",
              "tri/quad", "llvmpipe_ms", "facet_cyc", "cyc_ratio");
  for (const auto& d : metricDefs()) {
    const double hv = d.get(hw.m);
    int at = -1;
    for (std::size_t i = 0; i < facets.size(); ++i)
      if (noWorse(d, d.get(facets[i].m), hv)) {
        at = int(i);
        break;
      }
    nlohmann::json j;
    j["metric"] = d.key;
    j["hw"] = jnum(hv);
    if (at < 0) {
      double best = d.higher_better ? -1e300 : 1e300;
      for (const auto& r : facets) best = d.higher_better ? std::max(best, d.get(r.m)) : std::min(best, d.get(r.m));
      // Extrapolation from the two finest levels: error ∝ N^b (lower-better metrics),
      // 1 − SSIM ∝ N^b, PSNR linear in log N.
      double extra = NAN;
      if (facets.size() >= 2) {
        const Row& a = facets[facets.size() - 2];
        const Row& b = facets.back();
        auto tr = [&](double v) {
          if (d.key == std::string("psnr_db")) return v;
          if (d.key == std::string("ssim")) return std::log(std::max(1e-300, 1 - v));
          return v > 0 ? std::log(v) : NAN;
        };
        const double ya = tr(d.get(a.m)), yb = tr(d.get(b.m)), yt = tr(hv);
        const double xa = std::log(double(a.primitives)), xb = std::log(double(b.primitives));
        if (std::isfinite(ya) && std::isfinite(yb) && std::isfinite(yt) && xb > xa && yb != ya) {
          const double slope = (yb - ya) / (xb - xa);
          const bool improving = d.higher_better && d.key == std::string("psnr_db") ? slope > 0 : slope < 0;
          if (improving) extra = std::exp(xb + (yt - yb) / slope);
          if (extra > 1e12) extra = INFINITY;
        }
      }
      std::printf("%-24s %10s %10s %6s (not reached up to level %d; best facets %s; %s)\n", d.label, fmt(hv, 4).c_str(),
                  "-", "-", facets.back().level, fmt(best, 4).c_str(),
                  std::isinf(extra)      ? "extrapolated beyond 1e12 triangles"
                  : std::isfinite(extra) ? ("extrapolated ~" + fmt(extra, 0) + " triangles").c_str()
                                       : "no extrapolation: the accelerator's error is 0 or the trend is flat");
      j["reached"] = false;
      j["best_facets"] = jnum(best);
      j["extrapolated_triangles"] = jnum(extra);
    } else {
      const Row& r = facets[std::size_t(at)];
      const double ratio = (r.cycles && hw.cycles) ? double(r.cycles) / double(hw.cycles) : NAN;
      std::printf("%-24s %10s %10s %6d %9zu %8.1f %11.1f %11s %8s\n", d.label, fmt(hv, 4).c_str(),
                  fmt(d.get(r.m), 4).c_str(), r.level, r.primitives, double(r.primitives) / double(hw.primitives),
                  r.gl_ms, r.cycles ? std::to_string(r.cycles).c_str() : "-", fmt(ratio, 2).c_str());
      j["reached"] = true;
      j["facets"] = jnum(d.get(r.m));
      j["level"] = r.level;
      j["triangles"] = r.primitives;
      j["facets_host_ms"] = r.host_ms;
      j["facets_draw_ms"] = r.draw_ms;
      j["facets_gl_ms"] = r.gl_ms;
      j["hw_host_ms"] = hw.host_ms;
      j["facet_cycles"] = r.cycles;
      j["quadric_cycles"] = hw.cycles;
    }
    jEqual.push_back(j);
  }

  return jEqual;
}

}  // namespace qacc::compare
