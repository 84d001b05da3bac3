// qacc reduce SCENE: the degree-reduction study of issue 6. For every "algebraic" object of
// the scene and every level, the quadric pieces are built and measured against the true
// surface: quadric count (cells kept, distinct quadrics), sampled geometric error, and image
// error of a render of the pieces (reference renderer on the pieces, or the accelerator)
// against the exact ray-cast of the true surface (coverage differences, missing pixels,
// pinholes, PSNR); and the triangle count of a marching-tetrahedra mesh of the same
// surface whose geometric error is no worse (facets at equal error).
#include <cstdio>
#include <fstream>
#include <memory>
#include <sstream>

#include <nlohmann/json.hpp>

#include "modeling/algebraic/algebraic_object.h"
#include "modeling/algebraic/marching_tetrahedra.h"
#include "modeling/loader/scene_loader.h"
#include "raster/metrics/coverage_error.h"
#include "hw_model/report/stats_file.h"
#include "raster/metrics/psnr.h"
#include "tools/cli/commands.h"
#include "tools/cli/list_option.h"
#include "tools/cli/limit_options.h"
#include "tools/cli/threads_option.h"
#include "tools/engines/engine.h"

namespace qacc {

namespace {

struct ReduceArgs {
  std::string scene;
  std::string levels = "2,4,8,16";
  std::string engine = "reference";
  int threads = 0;
  std::string out;  // results: OUT.json and OUT.csv (one row per object and level)
  Limits limits;
};

std::vector<int> parseLevels(const std::string& s) { return parseIntListOption(s, "--levels", "a level", 1, 256); }

// Background pixels whose 8 neighbours are all covered.
int closedPinholes(const FrameBuffer& fb) {
  int n = 0;
  for (int y = 1; y + 1 < fb.height; ++y)
    for (int x = 1; x + 1 < fb.width; ++x) {
      if (fb.object[std::size_t(y) * fb.width + x] >= 0) continue;
      bool closed = true;
      for (int dy = -1; dy <= 1 && closed; ++dy)
        for (int dx = -1; dx <= 1; ++dx) closed = closed && fb.object[std::size_t(y + dy) * fb.width + (x + dx)] >= 0;
      n += closed;
    }
  return n;
}

void runReduce(const ReduceArgs& a) {
  const std::string text = readSceneText(a.scene, a.limits);
  const std::string dir = sceneDirectory(a.scene);
  const std::vector<int> levels = parseLevels(a.levels);

  // The strict loader first, so that bad scenes get its messages; then the raw JSON to patch.
  const Scene truthScene = parseScene(text, a.scene, dir, a.limits);
  const nlohmann::json doc = nlohmann::json::parse(text);
  EngineOptions eo;
  eo.threads = a.threads;
  eo.report_accuracy = false;
  const FrameBuffer truth = runEngine("reference", truthScene, eo).fb;
  const auto& objects = doc.at("objects");
  bool anyAlgebraic = false;
  for (const auto& o : objects) anyAlgebraic |= o.is_object() && o.value("type", "") == "algebraic";
  if (!anyAlgebraic)
    throw std::invalid_argument(a.scene + ": /objects: no object of type \"algebraic\" (reduce studies degree reduction)");
  nlohmann::ordered_json rows = nlohmann::ordered_json::array();
  for (std::size_t oi = 0; oi < objects.size(); ++oi) {
    if (objects[oi].value("type", "") != "algebraic") continue;
    const JsonNode node(objects[oi], "/objects/" + std::to_string(oi), std::make_shared<const std::string>(a.scene));
    const AlgebraicSpec spec = readAlgebraicSpec(node);
    std::printf("object %zu: %s, degree %d, box diagonal %.4g, engine %s, %dx%d\n", oi, spec.f.toString().c_str(),
                spec.f.degree(), spec.box.diagonal().norm(), a.engine.c_str(), truthScene.width, truthScene.height);
    std::printf("%6s %7s %7s %8s %11s %11s %9s %8s %8s %8s %8s %10s %6s\n", "level", "cells", "kept", "distinct",
                "geo_max", "geo_mean", "cov_diff", "missing", "spurious", "pinhole", "psnr_dB", "triangles",
                "mt_lvl");
    for (int L : levels) {
      DegreeReductionOptions o = spec.options;
      o.level = L;
      o.refine_error = 0;
      const DegreeReductionResult r = reduceAlgebraic(spec.f, spec.box, o);
      nlohmann::json patched = doc;
      patched["objects"][oi]["level"] = L;
      patched["objects"][oi].erase("refine_error");
      Scene pieces = parseScene(patched.dump(), a.scene, dir, a.limits);
      for (auto& so : pieces.objects) so.exact_surface = -1;  // draw the pieces
      const FrameBuffer fb = runEngine(a.engine, pieces, eo).fb;
      const CoverageError ce = coverageError(truth, fb);
      std::size_t diff = 0;
      for (std::size_t i = 0; i < fb.object.size(); ++i) diff += (fb.object[i] >= 0) != (truth.object[i] >= 0);
      // Facets at equal error: the coarsest marching-tetrahedra level whose error is no worse.
      long long tris = -1;
      int mtLevel = -1;
      for (int m = 2; m <= 256; m = m * 3 / 2 + 1) {
        const TriangleSoup mesh = marchingTetrahedra(spec.f, spec.box, m);
        if (!mesh.triangles.empty() && facetError(spec.f, mesh, spec.box).max <= r.error.max()) {
          tris = (long long)mesh.triangles.size();
          mtLevel = m;
          break;
        }
      }
      std::printf("%6d %7d %7d %8d %11.3e %11.3e %9zu %8zu %8zu %8d %8.2f %10lld %6d\n", L, r.cells, r.kept_cells,
                  r.distinct_quadrics, r.error.max(), 0.5 * (r.error.mean_piece_to_surface + r.error.mean_surface_to_piece),
                  diff, ce.pinholes, ce.spurious, closedPinholes(fb), psnr(truth, fb), tris, mtLevel);
      std::fflush(stdout);
      nlohmann::ordered_json row;
      row["object"] = oi;
      row["level"] = L;
      row["engine"] = a.engine;
      row["cells"] = r.cells;
      row["kept"] = r.kept_cells;
      row["distinct_quadrics"] = r.distinct_quadrics;
      row["geometric_error_max"] = r.error.max();
      row["geometric_error_mean"] = 0.5 * (r.error.mean_piece_to_surface + r.error.mean_surface_to_piece);
      row["coverage_diff"] = diff;
      row["missing"] = ce.pinholes;
      row["spurious"] = ce.spurious;
      row["closed_pinholes"] = closedPinholes(fb);
      row["psnr_db"] = jsonNumber(psnr(truth, fb));
      row["mt_triangles"] = tris;
      row["mt_level"] = mtLevel;
      rows.push_back(row);
    }
  }
  if (!a.out.empty()) writeResultRows(a.out, "qacc-reduce/1", rows);
}

}  // namespace

void addReduceCommand(CLI::App& app) {
  auto args = std::make_shared<ReduceArgs>();
  CLI::App* cmd = app.add_subcommand(
      "reduce", "Degree-reduction study of the scene's algebraic objects: quadric count vs geometric and image error, "
                "and marching-tetrahedra triangles at equal error");
  cmd->add_option("scene", args->scene, "Scene file")->required();
  cmd->add_option("--levels", args->levels, "Comma-separated Kuhn levels (cubes per axis)");
  cmd->add_option("--engine", args->engine, "Renderer of the pieces: reference|hw|hw-cycle");
  addThreadsOption(cmd, args->threads);
  cmd->add_option("--out", args->out, "Write the table as OUT.json and OUT.csv");
  addLimitOptions(cmd, args->limits);
  cmd->callback([args] { runReduce(*args); });
}

}  // namespace qacc
