// qacc compare SCENE [--tolerances 4,2,1,0.5,0.25 | --levels 8,32,128,512] [--sizes WxH,...]
//               [--out DIR] [--shading gouraud|pixel] [--config hw.json] [--threads N]
//               [--width W --height H] [--no-facet-cycles]
//
// Quadrics against triangles (design §4); the stages are in tools/compare/ (compare.h). Renders the exact reference, the accelerator
// (`hw` for the image and host time, `hw-cycle` for modeled cycles; the two are
// bit-identical by design) and, at every tessellation setting (a screen-space tolerance in
// pixels: every primitive to at most that projected chord error in the scene's view; or a
// level of triangles per primitive), the facets through OSMesa (image; context, upload and
// draw timed apart) and the same triangles through the accelerator's flat-facet path
// (modeled cycles). Every image is measured against the reference (PSNR, SSIM, coverage
// errors, silhouette distance, depth error). Then:
//  - equal error: per metric, the smallest tessellation that reaches the accelerator,
//    interpolated between measured settings, at most one step beyond the finest (else "not
//    reached", with the finest measured);
//  - equal cost: the facets' errors at the accelerator's primitive count, modeled cycles
//    and host time (hw's frame against llvmpipe's draw alone; the nearest setting, log scale);
//  - with --sizes, instead, the crossover: the same view at every size, facet cycles over quadric
//    cycles at equal silhouette error against the mean projected primitive size
//    (compare/crossover.h; plots: tools/plot_crossover.py).
// Objects with an exact surface (algebraic surfaces) are ray-cast exactly by the reference,
// drawn as their quadric pieces by the accelerator and as triangles of the true surface by
// the facets (modeling/tessellation.h), so both approximations are measured against the truth.
// Writes DIR/compare.json, DIR/compare.csv, DIR/side_by_side.png (composed with labels by
// tools/compose_side_by_side.py from DIR/panels/ and DIR/side_by_side.json; top: reference | quadrics |
// facets; bottom: luma-error heat maps of quadrics and facets | the facets' coverage errors) and SVG plots of every
// metric against triangles and against modeled cycles (DIR/error_vs_triangles.svg,
// DIR/error_vs_cycles.svg), drawn by tools/report/svg_plot.h.
#include <memory>

#include "tools/cli/commands.h"
#include "tools/cli/limit_options.h"
#include "tools/cli/threads_option.h"
#include "tools/cli/view_cull_option.h"
#include "tools/compare/compare.h"

namespace qacc {

void addCompareCommand(CLI::App& app) {
  auto o = std::make_shared<compare::CompareOptions>();
  CLI::App* cmd = app.add_subcommand("compare", "Quadrics (accelerator) vs triangles (OSMesa) at equal error and equal cost");
  cmd->add_option("scene", o->scene_path, "Scene file (qacc-scene/1 JSON)")->required();
  cmd->add_option("--tolerances", o->tolerances,
                  std::string("Tessellation to a screen-space error: pixels of projected chord error, comma separated "
                              "(default ") + compare::kDefaultTolerances + ")");
  cmd->add_option("--levels", o->levels,
                  "Tessellation levels instead: triangles per primitive, comma separated (excludes --tolerances)");
  cmd->add_option("--sizes", o->sizes,
                  "Crossover: the same view at every WIDTHxHEIGHT, comma separated (e.g. 256x192,512x384,...,4096x3072); "
                  "writes crossover.json and crossover.csv");
  cmd->add_option("--out", o->out_dir, "Output directory")->capture_default_str();
  cmd->add_option("--shading", o->shading, "Facet shading: gouraud|pixel")->capture_default_str();
  cmd->add_option("--config", o->config_path, "Accelerator configuration JSON");
  addThreadsOption(cmd, o->threads);
  cmd->add_option("--width", o->width, "Image width (with --height)");
  cmd->add_option("--height", o->height, "Image height (with --width)");
  addLimitOptions(cmd, o->limits);
  addViewCullOption(cmd, o->view_cull);
  cmd->add_flag("--no-facet-cycles", o->no_facet_cycles, "Skip the facet-path cycle runs on the accelerator");
  cmd->callback([o] { compare::runCompare(*o); });
}

}  // namespace qacc
