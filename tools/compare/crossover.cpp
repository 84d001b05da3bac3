#include "tools/compare/crossover.h"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <filesystem>
#include <sstream>

#include <nlohmann/json.hpp>

#include "tools/compare/equal_error.h"
#include "tools/compare/facet_levels.h"
#include "tools/compare/number_format.h"
#include "tools/compare/quadric_runs.h"
#include "tools/compare/report_files.h"
#include "tools/report/build_info.h"
#include "tools/report/python_tool.h"

namespace qacc::compare {

double crossoverSilhouetteTarget(double hwHausdorff) { return std::max(1.0, hwHausdorff); }

BreakEven breakEven(std::vector<SizeRatio> points) {
  points.erase(std::remove_if(points.begin(), points.end(),
                              [](const SizeRatio& p) { return !(p.ratio > 0) || !(p.px_per_primitive > 0); }),
               points.end());
  std::stable_sort(points.begin(), points.end(),
                   [](const SizeRatio& a, const SizeRatio& b) { return a.px_per_primitive < b.px_per_primitive; });
  BreakEven b;
  for (std::size_t i = 1; i < points.size(); ++i) {
    const double ya = std::log(points[i - 1].ratio), yb = std::log(points[i].ratio);
    if ((ya > 0) == (yb > 0) && ya != 0 && yb != 0) continue;
    if (ya == yb) continue;  // both exactly 1
    const double t = ya / (ya - yb);
    const double xa = std::log(points[i - 1].px_per_primitive), xb = std::log(points[i].px_per_primitive);
    b.found = true;
    b.px_per_primitive = std::exp(xa + t * (xb - xa));
    b.quadrics_pay_below = ya > yb;
    return b;
  }
  return b;
}

namespace {

struct SizeResult {
  ImageSize size;
  std::size_t covered_px = 0, visible_primitives = 0;
  double px_per_primitive = 0;
  Row hw;
  double target = 0;
  EqualErrorPoint point;
  double triangles = NAN, facet_cycles = NAN, ratio = NAN, draw_ms = NAN;
  std::vector<Row> facets;
};

const MetricDef& hausdorffDef() {
  for (const auto& d : metricDefs())
    if (std::string(d.key) == "silhouette_hausdorff_px") return d;
  throw std::logic_error("no silhouette metric");
}

}  // namespace

void runCrossover(const ComparePlan& plan, const CompareOptions& o) {
  namespace fs = std::filesystem;
  std::printf("\ncrossover by screen size: the same view at %zu sizes; facet-path cycles at the accelerator's "
              "silhouette error (Hausdorff, floored at 1 px) over quadric-path cycles\n",
              plan.sizes.size());
  // Work estimate: pixels of every image rendered (reference, hw, hw-cycle, and per setting the
  // facets twice, colour and ids, and once through the facet path).
  double pixels = 0;
  for (const auto& s : plan.sizes) pixels += double(s.width) * s.height;
  std::printf("work: %.1f Mpixel over all sizes x (3 + 2 x %zu settings) images; facet-path cycle runs above %zu "
              "triangles are skipped (no ratio there)\n",
              pixels / 1e6, plan.settings.size(), o.max_cycle_triangles);
  std::vector<SizeResult> results;
  for (const ImageSize& sz : plan.sizes) {
    ComparePlan p = plan;
    p.scene.width = sz.width;
    p.scene.height = sz.height;
    QuadricRuns q = renderQuadrics(p, o.threads);
    SizeResult r;
    r.size = sz;
    std::vector<bool> seen(p.scene.primitives.size(), false);
    for (std::size_t i = 0; i < q.ref.pixels(); ++i) {
      if (q.ref.object[i] < 0) continue;
      ++r.covered_px;
      const int prim = q.ref.primitive[i];
      if (prim >= 0 && std::size_t(prim) < seen.size() && !seen[std::size_t(prim)]) {
        seen[std::size_t(prim)] = true;
        ++r.visible_primitives;
      }
    }
    r.px_per_primitive = double(r.covered_px) / double(std::max<std::size_t>(1, p.scene.primitives.size()));
    FacetRuns f = renderFacetSettings(p.scene, p, o, q.ref);
    r.hw = std::move(q.hw);
    r.hw.fb = FrameBuffer();
    for (auto& row : f.rows) row.fb = FrameBuffer();
    r.target = crossoverSilhouetteTarget(r.hw.m.hausdorff);
    Row target = r.hw;
    target.m.hausdorff = r.target;
    r.point = equalErrorOf(hausdorffDef(), target, f.rows);
    if (r.point.found()) {
      r.triangles = r.point.cost;
      r.facet_cycles = rowValueAt(r.point, f.rows, [](const Row& x) { return double(x.cycles); });
      r.draw_ms = rowValueAt(r.point, f.rows, [](const Row& x) { return x.draw_ms; });
      r.ratio = r.hw.cycles ? r.facet_cycles / double(r.hw.cycles) : NAN;
    }
    r.facets = std::move(f.rows);
    std::printf("  %5dx%-5d %9.1f px/primitive  hw %llu cycles, silhouette %.2f px (target %.2f)  facets %s: %s "
                "triangles, %s cycles, ratio %s\n",
                sz.width, sz.height, r.px_per_primitive, (unsigned long long)r.hw.cycles, r.hw.m.hausdorff, r.target,
                equalErrorStatusName(r.point.status), fmt(r.triangles, 0).c_str(), fmt(r.facet_cycles, 0).c_str(),
                fmt(r.ratio, 2).c_str());
    results.push_back(std::move(r));
  }
  std::vector<SizeRatio> pts;
  for (const auto& r : results) pts.push_back({r.px_per_primitive, r.ratio});
  const BreakEven be = breakEven(pts);
  if (be.found)
    std::printf("break-even: %.1f px per primitive (quadrics pay %s it)\n", be.px_per_primitive,
                be.quadrics_pay_below ? "below" : "above");
  else
    std::printf("break-even: not reached in the measured range\n");

  nlohmann::json out;
  out["format"] = "qacc-crossover/1";
  out["qacc_version"] = qaccVersion();
  out["scene"] = plan.scene.name;
  out["scene_file"] = o.scene_path;
  out["quadric_primitives"] = plan.scene.primitives.size();
  out["hw_config"] = o.config_path.empty() ? "default" : o.config_path;
  out["clock_mhz"] = plan.cfg.clock_mhz;
  out["engines"] = {{"quadrics", "hw-cycle (the accelerator's quadric path)"},
                    {"facets", "hw-cycle flat-facet path (cycles); OSMesa llvmpipe (silhouette)"},
                    {"reference", "exact ray casting"}};
  out["equal_error_metric"] = "silhouette Hausdorff distance to the reference, px, target max(hw, 1 px)";
  out["primitive_size"] = "pixels the reference covers / quadric primitives in the scene";
  std::vector<std::string> settings;
  for (const auto& s : plan.settings) settings.push_back(s.label());
  out["facet_settings"] = settings;
  out["break_even"] = {{"found", be.found},
                       {"px_per_primitive", be.found ? jnum(be.px_per_primitive) : nlohmann::json(nullptr)},
                       {"quadrics_pay", be.found ? (be.quadrics_pay_below ? "below" : "above") : "n/a"}};
  out["sizes"] = nlohmann::json::array();
  std::ostringstream csv;
  csv << "# qacc crossover " << qaccVersion() << ", scene " << o.scene_path << ", accelerator config "
      << (o.config_path.empty() ? "default" : o.config_path)
      << ", quadrics: hw-cycle quadric path, facets: hw-cycle flat-facet path at the accelerator's silhouette error\n";
  csv << "scene,width,height,covered_px,visible_primitives,px_per_primitive,quadric_cycles,hw_hausdorff_px,target_px,"
         "status,triangles,facet_cycles,cycle_ratio,facets_draw_ms\n";
  for (const auto& r : results) {
    nlohmann::json j;
    j["width"] = r.size.width;
    j["height"] = r.size.height;
    j["covered_px"] = r.covered_px;
    j["visible_primitives"] = r.visible_primitives;
    j["px_per_primitive"] = r.px_per_primitive;
    j["quadric_cycles"] = r.hw.cycles;
    j["hw_host_ms"] = r.hw.host_ms;
    j["hw_hausdorff_px"] = jnum(r.hw.m.hausdorff);
    j["target_px"] = r.target;
    j["status"] = equalErrorStatusName(r.point.status);
    j["triangles"] = jnum(r.triangles);
    j["facet_cycles"] = jnum(r.facet_cycles);
    j["cycle_ratio"] = jnum(r.ratio);
    j["facets_draw_ms"] = jnum(r.draw_ms);
    j["facets"] = nlohmann::json::array();
    for (const auto& f : r.facets)
      j["facets"].push_back({{"setting", f.setting()},
                             {"tolerance_px", f.tolerance_px},
                             {"level", f.level},
                             {"triangles", f.primitives},
                             {"cycles", f.cycles},
                             {"draw_ms", f.draw_ms},
                             {"silhouette_hausdorff_px", jnum(f.m.hausdorff)},
                             {"achieved_max_pixel_error", jnum(f.achieved_px)}});
    out["sizes"].push_back(j);
    csv << plan.scene.name << "," << r.size.width << "," << r.size.height << "," << r.covered_px << ","
        << r.visible_primitives << "," << fmt(r.px_per_primitive, 3) << "," << r.hw.cycles << ","
        << fmt(r.hw.m.hausdorff, 3) << "," << fmt(r.target, 3) << "," << equalErrorStatusName(r.point.status) << ","
        << fmt(r.triangles, 0) << "," << fmt(r.facet_cycles, 0) << "," << fmt(r.ratio, 4) << ","
        << fmt(r.draw_ms, 2) << "\n";
  }
  writeText((fs::path(o.out_dir) / "crossover.json").string(), out.dump(2) + "\n");
  writeText((fs::path(o.out_dir) / "crossover.csv").string(), csv.str());
  const std::string plotted = runPythonTool("plot_crossover.py", o.out_dir);
  std::printf("wrote %s/{crossover.json, crossover.csv%s}\n", o.out_dir.c_str(),
              plotted.empty() ? ", crossover.png, crossover.svg" : "");
  if (!plotted.empty())
    std::printf("note: crossover plot not drawn: %s (run tools/plot_crossover.py %s)\n", plotted.c_str(),
                o.out_dir.c_str());
}

}  // namespace qacc::compare
