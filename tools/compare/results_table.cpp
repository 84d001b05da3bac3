#include "tools/compare/results_table.h"

#include <cstdio>
#include <string>

#include "tools/compare/number_format.h"

namespace qacc::compare {

void printResultsTable(const Scene& scene, const QuadricRuns& quadrics, const FacetRuns& facets) {
  const Row& hw = quadrics.hw;
  const std::string& shadingUsed = facets.shading_used;
  const std::string& glRenderer = facets.gl_renderer;
  const std::string& glVersion = facets.gl_version;
  const std::string& note = facets.note;
  const std::size_t exactSurfaces = facets.exact_surfaces;
  const double refMs = quadrics.ref_ms;
  std::printf("%s: %zu quadric primitives, %dx%d; facets: %s shading, %s, %s\n", scene.name.c_str(),
              scene.primitives.size(), scene.width, scene.height, shadingUsed.c_str(), glRenderer.c_str(),
              glVersion.c_str());
  if (!note.empty()) std::printf("note: %s\n", note.c_str());
  if (exactSurfaces)
    std::printf("%zu exact surface(s): the reference ray-casts the true surface, hw draws its quadric pieces, the "
                "facets are marching tetrahedra of the true surface (chord = sampled distance to it)\n",
                exactSurfaces);
  std::printf("reference: %.1f ms (exact ray casting)\n", refMs);
  std::printf("(eps: the tessellation's tolerance, pixels; tess_px: its achieved projected chord error; haus: the "
              "silhouette Hausdorff distance to the reference, pixels)\n");
  std::printf("%-8s %-13s %7s %9s %9s %9s %11s %9s %8s %7s %7s %7s %7s %7s %8s %8s %9s\n", "engine", "setting",
              "tess_px", "prims", "host_ms", "draw_ms", "cycles", "model_ms", "PSNR", "SSIM", "wrong", "pinhol", "spur",
              "haus", "chamfer", "dLSBmean", "chord");
  auto printRow = [&](const Row& r) {
    std::printf("%-8s %-13s %7s %9zu %9.1f %9s %11s %9s %8s %7.4f %7zu %7zu %7zu %7s %7s %8s %9s\n", r.engine.c_str(),
                r.engine == "facets" ? r.setting().c_str() : "-",
                r.tolerance_px > 0 ? fmt(r.achieved_px, 2).c_str() : "-", r.primitives, r.host_ms,
                r.draw_ms > 0 ? fmt(r.draw_ms, 1).c_str() : "-",
                r.cycles ? std::to_string(r.cycles).c_str() : "-", r.cycles ? fmt(r.modeled_ms, 3).c_str() : "-",
                fmt(r.m.psnr, 2).c_str(), r.m.ssim, r.m.wrong, r.m.pinholes, r.m.spurious, fmt(r.m.hausdorff, 2).c_str(),
                fmt(r.m.chamfer, 3).c_str(), fmt(r.m.depth_mean_lsb, 1).c_str(),
                r.engine == "facets" ? sci(r.chord_error).c_str() : "-");
  };
  printRow(hw);
  for (const auto& r : facets.rows) printRow(r);
}

}  // namespace qacc::compare
