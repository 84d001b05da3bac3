#include "tools/compare/facet_levels.h"

#include <cstdio>
#include <utility>

#include "modeling/tessellation/facet_scene.h"
#include "tools/compare/stopwatch.h"
#include "tools/engines/facet_engine.h"
#include "tools/engines/hw_engine.h"

namespace qacc::compare {

FacetRuns renderFacetLevels(const ComparePlan& plan, const CompareOptions& o, const FrameBuffer& ref) {
  return renderFacetSettings(plan.scene, plan, o, ref);
}

FacetRuns renderFacetSettings(const Scene& scene, const ComparePlan& plan, const CompareOptions& o,
                              const FrameBuffer& ref) {
  FacetRuns f;
  for (const FacetSetting& s : plan.settings) {
    Row r;
    r.engine = "facets";
    r.level = s.level;
    r.tolerance_px = s.tolerance_px;
    TriangleMesh3 mesh;
    const auto t0 = Clock::now();
    FacetRun run = s.level > 0
                       ? renderFacetScene(scene, s.level, plan.shading, o.threads, o.limits.max_triangles, &mesh)
                       : renderFacetScene(scene, facetTessellationOptions(0, s.tolerance_px), plan.shading, o.threads,
                                          o.limits.max_triangles, &mesh);
    r.host_ms = msSince(t0);
    r.draw_ms = run.render.draw_ms;
    r.context_ms = run.render.context_ms;
    r.upload_ms = run.render.upload_ms;
    r.gl_ms = run.render.totalMs();
    r.tess_ms = run.tessellate_ms;
    r.primitives = mesh.size();
    r.chord_error = run.tessellation.max_chord_error;
    r.achieved_px = s.tolerance_px > 0 ? achievedMaxPixelError(run.tessellation) : 0;
    r.exact_grid = run.tessellation.exact_grid;
    r.unstitched_planes = run.tessellation.unstitched_planes;
    r.unstitched_pieces = run.tessellation.unstitched_pieces;
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
    std::fprintf(stderr, "  facets %s: %zu triangles%s%s, %.1f ms (draw %.1f ms), %llu cycles, silhouette %.2f px\n",
                 r.setting().c_str(), r.primitives,
                 r.exact_grid ? (" (true surface: marching grid " + std::to_string(r.exact_grid) + ")").c_str() : "",
                 r.unstitched_planes + r.unstitched_pieces
                     ? (", " + std::to_string(r.unstitched_planes) + " shared planes and " +
                        std::to_string(r.unstitched_pieces) + " pieces left unstitched")
                           .c_str()
                     : "",
                 r.host_ms, r.draw_ms, (unsigned long long)r.cycles, r.m.hausdorff);
    f.rows.push_back(std::move(r));
  }
  return f;
}

}  // namespace qacc::compare
