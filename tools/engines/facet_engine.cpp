#include "tools/engines/facet_engine.h"

#include <chrono>
#include <cstdio>
#include <stdexcept>
#include <utility>

namespace qacc {

TessellationOptions facetTessellationOptions(int level, double pixelError) {
  TessellationOptions to;
  to.chord_samples = 2;  // vertices, edge midpoints and the centre region: cheap enough for big scenes
  if (pixelError > 0) {
    to.pixel_error = pixelError;
  } else {
    if (level < 2) throw std::invalid_argument("facets: --level must be at least 2 (triangles per primitive)");
    to.triangles = level;
  }
  return to;
}

double achievedMaxPixelError(const TessellationReport& report) { return report.max_pixel_error; }
double achievedMeanPixelError(const TessellationReport& report) { return report.mean_pixel_error; }

FacetRun renderFacetScene(const Scene& scene, int level, FacetShading shading, int threads, std::size_t max_triangles,
                          TriangleMesh3* meshOut) {
  if (level < 2) throw std::invalid_argument("facets: --level must be at least 2 (triangles per primitive)");
  const std::size_t estimate = scene.primitives.size() * std::size_t(level);
  if (estimate > max_triangles)
    throw std::invalid_argument(Limits::exceeded("facets: level " + std::to_string(level) + " for " +
                                                     std::to_string(scene.primitives.size()) + " primitives",
                                                 estimate, "triangles", max_triangles, "max-triangles"));
  return renderFacetScene(scene, facetTessellationOptions(level, 0), shading, threads, max_triangles, meshOut);
}

FacetRun renderFacetScene(const Scene& scene, const TessellationOptions& to, FacetShading shading, int threads,
                          std::size_t max_triangles, TriangleMesh3* meshOut) {
  requireFacetRenderer();  // before tessellating: a missing facets module is reported first
  FacetRun run;
  const auto t0 = std::chrono::steady_clock::now();
  TessellationOptions bounded = to;
  bounded.max_scene_triangles = max_triangles;
  TriangleMesh3 mesh;
  try {
    mesh = tessellateScene(scene, bounded, &run.tessellation);
  } catch (const std::length_error& e) {
    throw std::invalid_argument(e.what());
  }
  run.tessellate_ms = std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - t0).count();
  if (mesh.size() > max_triangles)
    throw std::invalid_argument(Limits::exceeded("facets: the tessellation of " +
                                                     std::to_string(scene.primitives.size()) + " primitives",
                                                 mesh.size(), "triangles", max_triangles, "max-triangles"));
#ifdef QACC_HAVE_OSMESA
  FacetRenderOptions ro;
  ro.shading = shading;
  ro.threads = threads;
  run.render = renderFacets(scene, mesh, ro);
#else
  (void)shading;
  (void)threads;
#endif
  if (meshOut) *meshOut = std::move(mesh);
  return run;
}

bool runFacetEngine(const std::string& engine, const Scene& scene, const EngineOptions& options, EngineResult& out) {
  if (engine != "facets") return false;
  const int level = options.level > 0 ? options.level : kDefaultFacetLevel;
  FacetRun run = renderFacetScene(scene, level, parseFacetShading(options.shading), options.threads,
                                  options.limits.max_triangles);
  out.fb = std::move(run.render.fb);
  out.host_ms = run.tessellate_ms + run.render.totalMs();
  const TessellationReport& t = run.tessellation;
  char buf[512];
  std::snprintf(buf, sizeof buf,
                "facets: level %d, %zu triangles (%zu cap) from %zu primitives (%zu parametric, %zu planar, "
                "%zu marching tetrahedra, %zu empty), chord error max %.3g mean %.3g",
                level, t.triangles, t.cap_triangles, t.primitives, t.parametric, t.planar, t.marching, t.empty,
                t.max_chord_error, t.mean_chord_error);
  out.notes.push_back(buf);
  if (t.exact_surfaces) {
    std::snprintf(buf, sizeof buf,
                  "facets: %zu of the triangles tessellate %zu exact surface(s) instead of their quadric pieces "
                  "(marching tetrahedra of the true surface, grid up to %d cubes per axis)",
                  t.exact_triangles, t.exact_surfaces, t.exact_grid);
    out.notes.push_back(buf);
  }
  if (t.shared_planes) {
    std::snprintf(buf, sizeof buf,
                  "facets: %zu shared clip planes, %zu pieces rebuilt onto their shared boundaries; left as tessellated "
                  "(cracks possible there): %zu planes, %zu pieces",
                  t.shared_planes, t.stitched_pieces, t.unstitched_planes, t.unstitched_pieces);
    out.notes.push_back(buf);
  }
  std::snprintf(buf, sizeof buf,
                "facets: tessellate %.2f ms, GL context %.2f ms, upload %.2f ms, draw+finish %.2f ms, read back %.2f ms, "
                "id pass %.2f ms",
                run.tessellate_ms, run.render.context_ms, run.render.upload_ms, run.render.draw_ms, run.render.readback_ms, run.render.id_pass_ms);
  out.notes.push_back(buf);
  out.notes.push_back("facets: shading " + std::string(facetShadingName(run.render.shading_used)) + ", GL_RENDERER " +
                      run.render.gl_renderer + ", GL_VERSION " + run.render.gl_version);
  if (!run.render.note.empty()) out.notes.push_back("facets: " + run.render.note);
  if (!run.render.csg_pruning.empty()) out.notes.push_back("facets: " + run.render.csg_pruning);
  return true;
}

}  // namespace qacc
