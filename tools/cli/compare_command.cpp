// qacc compare SCENE [--levels 8,32,128,512] [--out DIR] [--shading gouraud|pixel]
//               [--config hw.json] [--threads N] [--width W --height H] [--no-facet-cycles]
//
// Quadrics against triangles (design §4). Renders the exact reference, the accelerator
// (`hw` for the image and host time, `hw-cycle` for modeled cycles; the two are
// bit-identical by design) and, at every tessellation level, the facets through OSMesa
// (image, host time) and the same triangles through the accelerator's flat-facet path
// (modeled cycles). Every image is measured against the reference (PSNR, SSIM, coverage
// errors, silhouette distance, depth error). Then:
//  - equal error: per metric, the smallest tessellation no worse than the accelerator;
//  - equal cost: the facets' errors at the accelerator's primitive count, modeled cycles
//    and host time (the nearest level, in log scale).
// When a metric is not reached, the number of triangles that would reach it is extrapolated
// from the two finest levels (power law in the triangle count).
// Objects with an exact surface (algebraic surfaces) are ray-cast exactly by the reference,
// drawn as their quadric pieces by the accelerator and as triangles of the true surface by
// the facets (modeling/tessellation.h), so both approximations are measured against the truth.
// Writes DIR/compare.json, DIR/compare.csv, DIR/side_by_side.png (top: reference | quadrics |
// facets; bottom: luma-error heat maps of quadrics and facets | the facets' coverage errors) and SVG plots of every
// metric against triangles and against modeled cycles (DIR/error_vs_triangles.svg,
// DIR/error_vs_cycles.svg), drawn by tools/svg_plot.h.
#include <nlohmann/json.hpp>

#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <functional>
#include <limits>
#include <memory>
#include <sstream>
#include <stdexcept>

#include "hw_model/config/hw_config.h"
#include "modeling/tessellation/facet_scene.h"
#include "modeling/loader/scene_loader.h"
#include "raster/metrics/coverage_error.h"
#include "raster/metrics/depth_error.h"
#include "raster/image/heat_map.h"
#include "raster/image/png_io.h"
#include "raster/metrics/psnr.h"
#include "raster/reference/reference_renderer.h"
#include "raster/metrics/silhouette_distance.h"
#include "raster/metrics/ssim.h"
#include "tools/cli/commands.h"
#include "tools/cli/limit_options.h"
#include "tools/engines/facet_engine.h"
#include "tools/engines/hw_engine.h"
#include "tools/report/svg_plot.h"

namespace qacc {

namespace {

using Clock = std::chrono::steady_clock;
double msSince(Clock::time_point t0) { return std::chrono::duration<double, std::milli>(Clock::now() - t0).count(); }

struct CompareOptions {
  std::string scene_path;
  std::string levels = "8,32,128,512";
  std::string out_dir = "compare_out";
  std::string shading = "gouraud";
  std::string config_path;
  int threads = 0;
  int width = 0, height = 0;
  bool no_facet_cycles = false;
  std::size_t max_cycle_triangles = 1000000;  // facet-path cycle runs above this are skipped
  Limits limits;
};

struct Metrics {
  double psnr = 0, ssim = 0;
  std::size_t wrong = 0, pinholes = 0, spurious = 0;
  double hausdorff = 0, chamfer = 0;
  double depth_mean_lsb = 0, depth_max_lsb = 0;
  double coverage() const { return double(wrong + pinholes + spurious); }
};

Metrics measure(const FrameBuffer& ref, const FrameBuffer& t, const Camera& cam, int zbits) {
  Metrics m;
  m.psnr = psnr(ref, t);
  m.ssim = ssim(ref, t);
  const CoverageError c = coverageError(ref, t);
  m.wrong = c.wrong_object;
  m.pinholes = c.pinholes;
  m.spurious = c.spurious;
  const SilhouetteDistance s = silhouetteDistance(ref, t);
  m.hausdorff = s.hausdorff;
  m.chamfer = s.mean;
  const DepthError d = depthError(ref, t, cam, zbits);
  m.depth_mean_lsb = d.mean_lsb;
  m.depth_max_lsb = d.max_lsb;
  return m;
}

struct MetricDef {
  const char* key;
  const char* label;
  bool higher_better;
  std::function<double(const Metrics&)> get;
};

const std::vector<MetricDef>& metricDefs() {
  static const std::vector<MetricDef> defs = {
      {"psnr_db", "PSNR dB", true, [](const Metrics& m) { return m.psnr; }},
      {"ssim", "SSIM", true, [](const Metrics& m) { return m.ssim; }},
      {"coverage_px", "coverage errors px", false, [](const Metrics& m) { return m.coverage(); }},
      {"silhouette_hausdorff_px", "silhouette Hausdorff px", false, [](const Metrics& m) { return m.hausdorff; }},
      {"silhouette_mean_px", "silhouette mean px", false, [](const Metrics& m) { return m.chamfer; }},
      {"depth_mean_lsb", "depth mean LSB", false, [](const Metrics& m) { return m.depth_mean_lsb; }},
  };
  return defs;
}

bool noWorse(const MetricDef& d, double v, double ref) {
  if (std::isnan(v) || std::isnan(ref)) return false;
  return d.higher_better ? v >= ref : v <= ref;
}

struct Row {
  std::string engine;  // "hw" or "facets"
  int level = 0;
  std::size_t primitives = 0;  // quadrics or triangles
  double host_ms = 0;          // total host time of the engine (facets: tessellation + GL)
  double draw_ms = 0;          // facets: GL draw + glFinish of the colour pass only
  double gl_ms = 0;            // facets: everything OSMesa did (context, arrays, both passes, read back)
  double tess_ms = 0;          // facets: tessellation (incl. chord-error measurement)
  std::uint64_t cycles = 0;    // modeled cycles (0 = not measured)
  double modeled_ms = 0;
  double chord_error = 0;      // facets: max chord error (world units)
  int exact_grid = 0;          // facets: marching grid of the exact surfaces (cubes per axis, 0 = none)
  Metrics m;
  FrameBuffer fb;
};

std::vector<int> parseLevels(const std::string& s) {
  std::vector<int> out;
  std::stringstream ss(s);
  std::string item;
  while (std::getline(ss, item, ',')) {
    if (item.empty()) continue;
    std::size_t pos = 0;
    int v = 0;
    try {
      v = std::stoi(item, &pos);
    } catch (...) {
      pos = 0;
    }
    if (pos != item.size() || v < 2 || v > 1000000)
      throw std::invalid_argument("--levels: '" + item + "' is not a level (an integer from 2 to 1000000)");
    out.push_back(v);
  }
  if (out.empty()) throw std::invalid_argument("--levels: no level given");
  std::sort(out.begin(), out.end());
  out.erase(std::unique(out.begin(), out.end()), out.end());
  return out;
}

nlohmann::json jnum(double v) {
  if (std::isfinite(v)) return v;
  return v > 0 ? "inf" : (v < 0 ? "-inf" : "nan");
}

std::string sci(double v) {
  if (!std::isfinite(v)) return std::isnan(v) ? "n/a" : (v > 0 ? "inf" : "-inf");
  char b[32];
  std::snprintf(b, sizeof b, "%.2e", v);
  return b;
}

std::string fmt(double v, int prec = 3) {
  if (std::isinf(v)) return v > 0 ? "inf" : "-inf";
  if (std::isnan(v)) return "n/a";
  char b[32];
  std::snprintf(b, sizeof b, "%.*f", prec, v);
  return b;
}

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

Image8 coverageOverlay(const FrameBuffer& ref, const FrameBuffer& t) {
  const Image8 mask = coverageErrorMask(ref, t);
  Image8 out(ref.width, ref.height, 3);
  for (std::size_t i = 0; i < ref.pixels(); ++i) {
    std::uint8_t c[3];
    for (int k = 0; k < 3; ++k) c[k] = std::uint8_t(ref.color.data[i * 3 + k] / 4);  // dimmed reference
    switch (mask.data[i]) {
      case 1: c[0] = 255; c[1] = 40; c[2] = 40; break;    // wrong object: red
      case 2: c[0] = 255; c[1] = 230; c[2] = 0; break;    // pinhole: yellow
      case 3: c[0] = 0; c[1] = 220; c[2] = 255; break;    // spurious: cyan
      default: break;
    }
    for (int k = 0; k < 3; ++k) out.data[i * 3 + k] = c[k];
  }
  return out;
}

void writeText(const std::string& path, const std::string& text) {
  std::ofstream f(path);
  if (!f) throw std::runtime_error("cannot write " + path);
  f << text;
}

void runCompare(const CompareOptions& o) {
  namespace fs = std::filesystem;
  Scene scene = loadScene(o.scene_path, o.limits);
  if ((o.width > 0) != (o.height > 0)) throw std::invalid_argument("--width and --height go together");
  if (o.width > 0) {
    scene.width = o.width;
    scene.height = o.height;
  }
  const std::vector<int> levels = parseLevels(o.levels);
  const FacetShading shading = parseFacetShading(o.shading);
  if (!facetRendererAvailable()) throw std::invalid_argument(facetRendererMissingMessage());
  const HwConfig cfg = o.config_path.empty() ? HwConfig() : loadHwConfig(o.config_path);
  fs::create_directories(o.out_dir);
  const int zbits = 24;

  std::fprintf(stderr, "compare %s: %zu primitives, %dx%d\n", scene.name.c_str(), scene.primitives.size(), scene.width,
               scene.height);
  auto t0 = Clock::now();
  const FrameBuffer ref = renderReference(scene, o.threads);
  const double refMs = msSince(t0);
  std::fprintf(stderr, "  reference %.1f ms\n", refMs);

  // Quadrics on the accelerator: image and host time from `hw`, cycles from `hw-cycle`.
  Row hw;
  hw.engine = "hw";
  hw.primitives = scene.primitives.size();
  HwStats st;
  t0 = Clock::now();
  hw.fb = renderWithHwEngine("hw", scene, cfg, o.threads, st);
  hw.host_ms = msSince(t0);
  HwStats stc;
  const FrameBuffer hwc = renderWithHwEngine("hw-cycle", scene, cfg, o.threads, stc);
  hw.cycles = stc.cycles;
  hw.modeled_ms = stc.frameSeconds() * 1e3;
  hw.m = measure(ref, hw.fb, scene.camera, zbits);
  const bool identical = hwc.color.data == hw.fb.color.data && hwc.object == hw.fb.object;
  std::fprintf(stderr, "  hw %.1f ms, hw-cycle %llu cycles (%s)\n", hw.host_ms, (unsigned long long)hw.cycles,
               identical ? "images bit-identical" : "IMAGES DIFFER");

  std::vector<Row> facets;
  std::string glRenderer, glVersion, shadingUsed, note;
  std::size_t exactSurfaces = 0;
  for (int level : levels) {
    Row r;
    r.engine = "facets";
    r.level = level;
    TriangleMesh3 mesh;
    t0 = Clock::now();
    FacetRun run = renderFacetScene(scene, level, shading, o.threads, o.limits.max_triangles, &mesh);
    r.host_ms = msSince(t0);
    r.draw_ms = run.render.draw_ms;
    r.gl_ms = run.render.totalMs();
    r.tess_ms = run.tessellate_ms;
    r.primitives = mesh.size();
    r.chord_error = run.tessellation.max_chord_error;
    r.exact_grid = run.tessellation.exact_grid;
    exactSurfaces = run.tessellation.exact_surfaces;
    glRenderer = run.render.gl_renderer;
    glVersion = run.render.gl_version;
    shadingUsed = facetShadingName(run.render.shading_used);
    if (!run.render.note.empty()) note = run.render.note;
    r.fb = std::move(run.render.fb);
    r.m = measure(ref, r.fb, scene.camera, zbits);
    if (!o.no_facet_cycles && mesh.size() <= o.max_cycle_triangles) {
      const Scene fsc = facetScene(scene, mesh);
      HwStats fst;
      renderWithHwEngine("hw-cycle", fsc, cfg, o.threads, fst);
      r.cycles = fst.cycles;
      r.modeled_ms = fst.frameSeconds() * 1e3;
    }
    std::fprintf(stderr, "  facets level %d: %zu triangles%s, %.1f ms, %llu cycles\n", level, r.primitives,
                 r.exact_grid ? (" (true surface: marching grid " + std::to_string(r.exact_grid) + ")").c_str() : "",
                 r.host_ms, (unsigned long long)r.cycles);
    facets.push_back(std::move(r));
  }

  // ---- table ----
  std::printf("%s: %zu quadric primitives, %dx%d; facets: %s shading, %s, %s\n", scene.name.c_str(),
              scene.primitives.size(), scene.width, scene.height, shadingUsed.c_str(), glRenderer.c_str(),
              glVersion.c_str());
  if (!note.empty()) std::printf("note: %s\n", note.c_str());
  if (exactSurfaces)
    std::printf("%zu exact surface(s): the reference ray-casts the true surface, hw draws its quadric pieces, the "
                "facets are marching tetrahedra of the true surface (chord = sampled distance to it)\n",
                exactSurfaces);
  std::printf("reference: %.1f ms (exact ray casting)\n", refMs);
  std::printf("%-8s %6s %9s %9s %9s %11s %9s %8s %7s %7s %7s %7s %7s %8s %8s %9s\n", "engine", "level", "prims",
              "host_ms", "draw_ms", "cycles", "model_ms", "PSNR", "SSIM", "wrong", "pinhol", "spur", "haus",
              "chamfer", "dLSBmean", "chord");
  auto printRow = [&](const Row& r) {
    std::printf("%-8s %6s %9zu %9.1f %9s %11s %9s %8s %7.4f %7zu %7zu %7zu %7s %7s %8s %9s\n", r.engine.c_str(),
                r.level ? std::to_string(r.level).c_str() : "-", r.primitives, r.host_ms,
                r.draw_ms > 0 ? fmt(r.draw_ms, 1).c_str() : "-",
                r.cycles ? std::to_string(r.cycles).c_str() : "-", r.cycles ? fmt(r.modeled_ms, 3).c_str() : "-",
                fmt(r.m.psnr, 2).c_str(), r.m.ssim, r.m.wrong, r.m.pinholes, r.m.spurious, fmt(r.m.hausdorff, 2).c_str(),
                fmt(r.m.chamfer, 3).c_str(), fmt(r.m.depth_mean_lsb, 1).c_str(),
                r.engine == "facets" ? sci(r.chord_error).c_str() : "-");
  };
  printRow(hw);
  for (const auto& r : facets) printRow(r);

  // ---- equal error ----
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
                  "-", "-", levels.back(), fmt(best, 4).c_str(),
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

  // ---- equal cost ----
  nlohmann::json jCost = nlohmann::json::object();
  std::printf("\nequal cost: facets nearest to the accelerator's budget (log scale)\n");
  struct Budget {
    const char* key;
    const char* label;
    double target;
    std::function<double(const Row&)> get;
  };
  const std::vector<Budget> budgets = {
      {"primitives", "same primitive count", double(hw.primitives), [](const Row& r) { return double(r.primitives); }},
      {"cycles", "same modeled cycles", double(hw.cycles), [](const Row& r) { return double(r.cycles); }},
      {"host_ms", "same host time", hw.host_ms, [](const Row& r) { return r.host_ms; }},
  };
  for (const auto& b : budgets) {
    const int i = nearestLog(facets, b.target, b.get);
    if (i < 0) {
      std::printf("  %-22s: not measured\n", b.label);
      continue;
    }
    const Row& r = facets[std::size_t(i)];
    std::printf("  %-22s: hw %s vs facets level %d (%s): PSNR %s vs %s, SSIM %.4f vs %.4f, coverage %zu vs %zu px, "
                "Hausdorff %s vs %s px\n",
                b.label, fmt(b.target, 1).c_str(), r.level, fmt(b.get(r), 1).c_str(), fmt(hw.m.psnr, 2).c_str(),
                fmt(r.m.psnr, 2).c_str(), hw.m.ssim, r.m.ssim, std::size_t(hw.m.coverage()), std::size_t(r.m.coverage()),
                fmt(hw.m.hausdorff, 2).c_str(), fmt(r.m.hausdorff, 2).c_str());
    nlohmann::json j;
    j["hw_budget"] = jnum(b.target);
    j["level"] = r.level;
    j["facets_budget"] = jnum(b.get(r));
    for (const auto& d : metricDefs()) {
      j["hw_" + std::string(d.key)] = jnum(d.get(hw.m));
      j["facets_" + std::string(d.key)] = jnum(d.get(r.m));
    }
    jCost[b.key] = j;
  }

  // ---- JSON / CSV ----
  auto rowJson = [&](const Row& r) {
    nlohmann::json j;
    j["engine"] = r.engine;
    j["level"] = r.level;
    j["primitives"] = r.primitives;
    j["host_ms"] = r.host_ms;
    j["draw_ms"] = r.draw_ms;
    j["gl_ms"] = r.gl_ms;
    j["tessellate_ms"] = r.tess_ms;
    j["cycles"] = r.cycles;
    j["modeled_ms"] = r.modeled_ms;
    j["chord_error"] = jnum(r.chord_error);
    j["exact_surface_grid"] = r.exact_grid;
    for (const auto& d : metricDefs()) j[d.key] = jnum(d.get(r.m));
    j["wrong_object_px"] = r.m.wrong;
    j["pinholes_px"] = r.m.pinholes;
    j["spurious_px"] = r.m.spurious;
    j["depth_max_lsb"] = jnum(r.m.depth_max_lsb);
    return j;
  };
  nlohmann::json out;
  out["scene"] = scene.name;
  out["scene_file"] = o.scene_path;
  out["width"] = scene.width;
  out["height"] = scene.height;
  out["quadric_primitives"] = scene.primitives.size();
  out["reference_ms"] = refMs;
  out["gl_renderer"] = glRenderer;
  out["gl_version"] = glVersion;
  out["facet_shading"] = shadingUsed;
  out["hw_config"] = o.config_path.empty() ? "default" : o.config_path;
  out["clock_mhz"] = cfg.clock_mhz;
  out["hw_cycle_identical_to_hw"] = identical;
  out["rows"] = nlohmann::json::array();
  out["rows"].push_back(rowJson(hw));
  for (const auto& r : facets) out["rows"].push_back(rowJson(r));
  out["equal_error"] = jEqual;
  out["equal_cost"] = jCost;
  writeText((fs::path(o.out_dir) / "compare.json").string(), out.dump(2) + "\n");

  std::ostringstream csv;
  csv << "scene,engine,level,primitives,host_ms,draw_ms,cycles,modeled_ms,chord_error";
  for (const auto& d : metricDefs()) csv << "," << d.key;
  csv << ",wrong_object_px,pinholes_px,spurious_px,depth_max_lsb,gl_renderer\n";
  auto rowCsv = [&](const Row& r) {
    csv << scene.name << "," << r.engine << "," << r.level << "," << r.primitives << "," << r.host_ms << ","
        << r.draw_ms << "," << r.cycles << "," << r.modeled_ms << "," << r.chord_error;
    for (const auto& d : metricDefs()) csv << "," << fmt(d.get(r.m), 6);
    csv << "," << r.m.wrong << "," << r.m.pinholes << "," << r.m.spurious << "," << fmt(r.m.depth_max_lsb, 3) << ",\""
        << (r.engine == "facets" ? glRenderer : std::string("qacc hw")) << "\"\n";
  };
  rowCsv(hw);
  for (const auto& r : facets) rowCsv(r);
  writeText((fs::path(o.out_dir) / "compare.csv").string(), csv.str());

  // ---- side-by-side image: reference | quadrics | facets / heat maps and coverage ----
  int shown = int(facets.size()) - 1;
  for (const auto& j : jEqual)
    if (j["metric"] == "psnr_db" && j.value("reached", false)) {
      for (std::size_t i = 0; i < facets.size(); ++i)
        if (facets[i].level == j["level"].get<int>()) shown = int(i);
    }
  const Row& fr = facets[std::size_t(shown)];
  const int W = scene.width, H = scene.height;
  Image8 sbs(3 * W, 2 * H, 3, 0);
  blit(sbs, ref.color, 0, 0);
  blit(sbs, hw.fb.color, W, 0);
  blit(sbs, fr.fb.color, 2 * W, 0);
  blit(sbs, heatMap(lumaDifference(ref.color, hw.fb.color), 64.0), 0, H);
  blit(sbs, heatMap(lumaDifference(ref.color, fr.fb.color), 64.0), W, H);
  blit(sbs, coverageOverlay(ref, fr.fb), 2 * W, H);
  writePng((fs::path(o.out_dir) / "side_by_side.png").string(), sbs);

  // ---- plots (SVG) ----
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
  writeText((fs::path(o.out_dir) / "error_vs_triangles.svg").string(),
            svgPlot(scene.name + ": error vs primitives (facets through OSMesa, quadrics on the accelerator)",
                    panels(false)));
  bool anyCycles = hw.cycles > 0;
  for (const auto& r : facets) anyCycles = anyCycles && r.cycles > 0;
  if (anyCycles)
    writeText((fs::path(o.out_dir) / "error_vs_cycles.svg").string(),
              svgPlot(scene.name + ": error vs modeled accelerator cycles (same hardware, facet path vs quadric path)",
                      panels(true)));
  std::printf("\nwrote %s/{compare.json, compare.csv, side_by_side.png (facets level %d), error_vs_triangles.svg%s}\n",
              o.out_dir.c_str(), fr.level, anyCycles ? ", error_vs_cycles.svg" : "");
}

}  // namespace

void addCompareCommand(CLI::App& app) {
  auto o = std::make_shared<CompareOptions>();
  CLI::App* cmd = app.add_subcommand("compare", "Quadrics (accelerator) vs triangles (OSMesa) at equal error and equal cost");
  cmd->add_option("scene", o->scene_path, "Scene file (qacc-scene/1 JSON)")->required();
  cmd->add_option("--levels", o->levels, "Tessellation levels: triangles per primitive, comma separated")
      ->capture_default_str();
  cmd->add_option("--out", o->out_dir, "Output directory")->capture_default_str();
  cmd->add_option("--shading", o->shading, "Facet shading: gouraud|pixel")->capture_default_str();
  cmd->add_option("--config", o->config_path, "Accelerator configuration JSON");
  cmd->add_option("--threads", o->threads, "Threads (default: all cores)")->check(CLI::Range(1, 1024));
  cmd->add_option("--width", o->width, "Image width (with --height)")->check(CLI::Range(1, kMaxImageSide));
  cmd->add_option("--height", o->height, "Image height (with --width)")->check(CLI::Range(1, kMaxImageSide));
  cmd->add_flag("--no-facet-cycles", o->no_facet_cycles, "Skip the facet-path cycle runs on the accelerator");
  addLimitOptions(cmd, o->limits);
  cmd->callback([o] { runCompare(*o); });
}

}  // namespace qacc
