#include "tools/compare/facet_levels.h"

#include <cstdio>
#include <utility>

#include "modeling/tessellation/facet_scene.h"
#include "tools/compare/stopwatch.h"
#include "tools/engines/facet_engine.h"
#include "tools/engines/hw_engine.h"

namespace qacc::compare {

FacetRuns renderFacetLevels(const ComparePlan& plan, const CompareOptions& o, const FrameBuffer& ref) {
  const Scene& scene = plan.scene;
  FacetRuns f;
  for (int level : plan.levels) {
    Row r;
    r.engine = "facets";
    r.level = level;
    TriangleMesh3 mesh;
    const auto t0 = Clock::now();
    FacetRun run = renderFacetScene(scene, level, plan.shading, o.threads, o.limits.max_triangles, &mesh);
    r.host_ms = msSince(t0);
    r.draw_ms = run.render.draw_ms;
    r.gl_ms = run.render.totalMs();
    r.tess_ms = run.tessellate_ms;
    r.primitives = mesh.size();
    r.chord_error = run.tessellation.max_chord_error;
    r.exact_grid = run.tessellation.exact_grid;
    f.exact_surfaces = run.tessellation.exact_surfaces;
    f.gl_renderer = run.render.gl_renderer;
    f.gl_version = run.render.gl_version;
    f.shading_used = facetShadingName(run.render.shading_used);
    if (!run.render.note.empty()) f.note = run.render.note;
    r.fb = std::move(run.render.fb);
    r.m = measure(ref, r.fb, scene.camera, plan.zbits);
    if (!o.no_facet_cycles && mesh.size() <= o.max_cycle_triangles) {
      const Scene fsc = facetScene(scene, mesh);
      HwStats fst;
      renderWithHwEngine("hw-cycle", fsc, plan.cfg, o.threads, fst);
      r.cycles = fst.cycles;
      r.modeled_ms = fst.frameSeconds() * 1e3;
    }
    std::fprintf(stderr, "  facets level %d: %zu triangles%s, %.1f ms, %llu cycles\n", level, r.primitives,
                 r.exact_grid ? (" (true surface: marching grid " + std::to_string(r.exact_grid) + ")").c_str() : "",
                 r.host_ms, (unsigned long long)r.cycles);
    f.rows.push_back(std::move(r));
  }
  return f;
}

}  // namespace qacc::compare
