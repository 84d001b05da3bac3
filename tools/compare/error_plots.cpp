#include "tools/compare/error_plots.h"

#include <filesystem>

#include "tools/compare/image_metrics.h"
#include "tools/compare/report_files.h"
#include "tools/report/svg_plot.h"

namespace qacc::compare {

bool writeErrorPlots(const std::string& outDir, const std::string& sceneName, const std::string& shadingUsed,
                     const Row& hw, const std::vector<Row>& facets) {
  namespace fs = std::filesystem;
  auto panels = [&](bool byCycles) {
    std::vector<PlotPanel> ps;
    for (const auto& d : metricDefs()) {
      PlotPanel p;
      p.title = d.label;
      p.xlabel = byCycles ? "modeled cycles" : "primitives (triangles or quadrics)";
      p.ylabel = d.label;
      p.log_x = true;
      PlotSeries s;
      s.label = "facets (" + shadingUsed + ")";
      for (const auto& r : facets) {
        const double x = byCycles ? double(r.cycles) : double(r.primitives);
        if (byCycles && r.cycles == 0) continue;
        s.x.push_back(x);
        s.y.push_back(d.get(r.m));
      }
      PlotSeries q;
      q.label = "quadrics (hw)";
      q.color = "#d62728";
      q.x.push_back(byCycles ? double(hw.cycles) : double(hw.primitives));
      q.y.push_back(d.get(hw.m));
      p.series = {s, q};
      p.lines.push_back({"hw level", "#d62728", d.get(hw.m)});
      ps.push_back(p);
    }
    return ps;
  };
  writeText((fs::path(outDir) / "error_vs_triangles.svg").string(),
            svgPlot(sceneName + ": error vs primitives (facets through OSMesa, quadrics on the accelerator)",
                    panels(false)));
  bool anyCycles = hw.cycles > 0;
  for (const auto& r : facets) anyCycles = anyCycles && r.cycles > 0;
  if (anyCycles)
    writeText((fs::path(outDir) / "error_vs_cycles.svg").string(),
              svgPlot(sceneName + ": error vs modeled accelerator cycles (same hardware, facet path vs quadric path)",
                      panels(true)));
  return anyCycles;
}

}  // namespace qacc::compare
