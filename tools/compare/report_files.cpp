#include "tools/compare/report_files.h"

#include <filesystem>
#include <fstream>
#include <sstream>
#include <stdexcept>

#include "tools/compare/image_metrics.h"
#include "tools/compare/number_format.h"
#include "tools/report/build_info.h"

namespace qacc::compare {

namespace fs = std::filesystem;

void writeText(const std::string& path, const std::string& text) {
  std::ofstream f(path);
  if (!f) throw std::runtime_error("cannot write " + path);
  f << text;
}

void writeCompareJson(const CompareOptions& o, const ComparePlan& plan, const QuadricRuns& quadrics,
                      const FacetRuns& facets, const nlohmann::json& jEqual, const nlohmann::json& jCost) {
  const Scene& scene = plan.scene;
  const Row& hw = quadrics.hw;
  auto rowJson = [&](const Row& r) {
    nlohmann::json j;
    j["engine"] = r.engine;
    j["setting"] = r.setting();
    j["level"] = r.level;
    j["tolerance_px"] = r.tolerance_px;
    j["achieved_max_pixel_error"] = jnum(r.achieved_px);
    j["primitives"] = r.primitives;
    j["host_ms"] = r.host_ms;
    j["draw_ms"] = r.draw_ms;
    j["context_ms"] = r.context_ms;
    j["upload_ms"] = r.upload_ms;
    j["gl_ms"] = r.gl_ms;
    j["tessellate_ms"] = r.tess_ms;
    j["cycles"] = r.cycles;
    j["modeled_ms"] = r.modeled_ms;
    j["chord_error"] = jnum(r.chord_error);
    j["exact_surface_grid"] = r.exact_grid;
    j["unstitched_shared_planes"] = r.unstitched_planes;
    j["unstitched_pieces"] = r.unstitched_pieces;
    for (const auto& d : metricDefs()) j[d.key] = jnum(d.get(r.m));
    j["wrong_object_px"] = r.m.wrong;
    j["pinholes_px"] = r.m.pinholes;
    j["spurious_px"] = r.m.spurious;
    j["depth_max_lsb"] = jnum(r.m.depth_max_lsb);
    return j;
  };
  nlohmann::json out;
  out["format"] = "qacc-compare/3";  // /3: unstitched_shared_boundaries split into planes and pieces
  out["qacc_version"] = qaccVersion();
  out["scene"] = scene.name;
  out["scene_file"] = o.scene_path;
  out["width"] = scene.width;
  out["height"] = scene.height;
  out["quadric_primitives"] = scene.primitives.size();
  out["reference_ms"] = quadrics.ref_ms;
  out["gl_renderer"] = facets.gl_renderer;
  out["gl_version"] = facets.gl_version;
  out["facet_shading"] = facets.shading_used;
  out["facet_settings"] = o.levels.empty() ? "tolerances (pixels of projected chord error)" : "levels (triangles per primitive)";
  out["hw_config"] = o.config_path.empty() ? "default" : o.config_path;
  out["clock_mhz"] = plan.cfg.clock_mhz;
  out["hw_cycle_identical_to_hw"] = quadrics.identical;
  out["rows"] = nlohmann::json::array();
  out["rows"].push_back(rowJson(hw));
  for (const auto& r : facets.rows) out["rows"].push_back(rowJson(r));
  out["equal_error"] = jEqual;
  out["equal_cost"] = jCost;
  writeText((fs::path(o.out_dir) / "compare.json").string(), out.dump(2) + "\n");
}

void writeCompareCsv(const CompareOptions& o, const Scene& scene, const QuadricRuns& quadrics, const FacetRuns& facets) {
  const Row& hw = quadrics.hw;
  const std::string& glRenderer = facets.gl_renderer;
  std::ostringstream csv;
  csv << "# qacc compare " << qaccVersion() << ", scene " << o.scene_path << " (" << scene.width << "x" << scene.height
      << "), accelerator config " << (o.config_path.empty() ? "default" : o.config_path) << ", facets "
      << facets.shading_used << " via " << facets.gl_renderer << "\n";
  csv << "scene,engine,setting,level,tolerance_px,achieved_max_pixel_error,primitives,host_ms,context_ms,upload_ms,"
         "draw_ms,cycles,modeled_ms,chord_error";
  for (const auto& d : metricDefs()) csv << "," << d.key;
  csv << ",wrong_object_px,pinholes_px,spurious_px,depth_max_lsb,gl_renderer\n";
  auto rowCsv = [&](const Row& r) {
    csv << scene.name << "," << r.engine << "," << r.setting() << "," << r.level << "," << r.tolerance_px << ","
        << fmt(r.achieved_px, 4) << "," << r.primitives << "," << r.host_ms << "," << r.context_ms << ","
        << r.upload_ms << "," << r.draw_ms << "," << r.cycles << "," << r.modeled_ms << "," << r.chord_error;
    for (const auto& d : metricDefs()) csv << "," << fmt(d.get(r.m), 6);
    csv << "," << r.m.wrong << "," << r.m.pinholes << "," << r.m.spurious << "," << fmt(r.m.depth_max_lsb, 3) << ",\""
        << (r.engine == "facets" ? glRenderer : std::string("qacc hw")) << "\"\n";
  };
  rowCsv(hw);
  for (const auto& r : facets.rows) rowCsv(r);
  writeText((fs::path(o.out_dir) / "compare.csv").string(), csv.str());
}

}  // namespace qacc::compare
