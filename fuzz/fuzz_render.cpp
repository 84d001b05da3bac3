// Fuzz target: a scene rendered tiny (24x18) by every engine. A scene the loader accepts must
// render without a crash or sanitizer report in the reference, hw and hw-cycle, and hw and
// hw-cycle must produce the same image (they are bit-identical by construction); hw-cycle's
// clocks — the item clock (engines/item_clock.h; the default configuration's, and with the
// hierarchical Z unit) and the ticking clock that repeats one tick's counts over cycles that
// cannot differ — must count what ticking every cycle counts (MachineClock::EveryCycle:
// every count of HwStats::countsJson — cycles, every unit's busy / stall / idle / items,
// pixel, overflow, hierarchical Z and CSG counters), and so must a render that reuses the
// setups, pixel trace and frame of one under other timing keys (DatapathReuse). The facets
// engine is represented by its tessellation (modeling/tessellation, the facets engine's
// options at a small level) of every accepted scene, whose mesh must be well formed (every
// index in range, one object / material / primitive index per triangle). Its GL draw
// (OSMesa llvmpipe) is left out: every frame creates an OSMesa context, 350-400 ms under
// ASan, and the draw only consumes the checked mesh (docs/FUZZING.md).
#include <atomic>
#include <cstddef>
#include <cstdint>
#include <cstdio>
#include <cstdlib>
#include <stdexcept>
#include <string>
#include <vector>

#include "hw_model/engines/cycle_engine.h"
#include "hw_model/engines/functional_engine.h"
#include "modeling/loader/scene_loader.h"
#include "modeling/scene/scene_error.h"
#include "modeling/tessellation/tessellation.h"
#include "raster/reference/reference_renderer.h"
#include "fuzz/json_mutator.h"

namespace {

// What the run did with its inputs, printed when it ends (libFuzzer's own statistics count
// executions, not how many scenes the loader accepted and every engine then drew).
struct RunCounts {
  std::atomic<unsigned long long> inputs{0}, refused{0}, drawn{0}, over_triangle_budget{0};
  ~RunCounts() {
    std::fprintf(stderr,
                 "fuzz_render: %llu inputs: %llu refused by the loader, %llu drawn by the reference, hw and "
                 "hw-cycle and tessellated (%llu of them over the triangle budget)\n",
                 inputs.load(), refused.load(), drawn.load(), over_triangle_budget.load());
  }
};
RunCounts counts;

// The facets engine's tessellation (tools/engines/facet_engine.cpp: facetTessellationOptions)
// at a level small enough for thousands of scenes a minute, bounded as --max-triangles bounds it.
void tessellateLikeFacets(const qacc::Scene& scene) {
  qacc::TessellationOptions to;
  to.chord_samples = 2;
  to.triangles = 8;
  to.max_scene_triangles = 20000;
  qacc::TriangleMesh3 mesh;
  try {
    mesh = qacc::tessellateScene(scene, to);
  } catch (const std::length_error&) {
    ++counts.over_triangle_budget;
    return;  // over the triangle budget: refused, as the facets engine refuses it
  }
  const std::size_t n = mesh.size();
  if (mesh.normals.size() != mesh.positions.size() || mesh.object.size() != n || mesh.material.size() != n ||
      mesh.primitive.size() != n)
    std::abort();
  for (std::size_t t = 0; t < n; ++t) {
    for (int v : mesh.triangles[t])
      if (v < 0 || std::size_t(v) >= mesh.positions.size()) std::abort();
    // -1: a triangle of the exact surface of an object that has no piece (view culling removed
    // them all; tessellation.cpp draws that surface all the same).
    if (mesh.primitive[t] < -1 || (mesh.primitive[t] >= 0 && std::size_t(mesh.primitive[t]) >= scene.primitives.size()))
      std::abort();
    if (mesh.object[t] < 0 || std::size_t(mesh.object[t]) >= scene.objects.size()) std::abort();
  }
}

}  // namespace

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  ++counts.inputs;
  qacc::Limits limits;
  limits.max_input_bytes = 1 << 20;
  limits.max_primitives = 2000;
  limits.max_cells = 5000;
  limits.max_clip_work = 10000000;  // about 30 ms of setup: up to 82 clip planes on one primitive
  qacc::Scene scene;
  try {
    scene = qacc::parseScene(std::string(reinterpret_cast<const char*>(data), size), "fuzz.json",
                             QACC_SOURCE_DIR "/scenes", limits);
  } catch (const qacc::SceneError&) {
    ++counts.refused;
    return 0;
  }
  scene.width = 24;
  scene.height = 18;
  qacc::renderReference(scene, 1);
  const qacc::HwConfig cfg;
  const qacc::HwRender a = qacc::renderHw(scene, cfg, 1);
  const qacc::HwRender b = qacc::renderHwCycle(scene, cfg, 1);
  if (!(a.fb.color.data == b.fb.color.data) || a.fb.object != b.fb.object) std::abort();
  // The engine's clock (the item clock for the default configuration), the ticking clock
  // that repeats, and the one that ticks every cycle: every count must agree (countsJson
  // leaves out the cycles the repeating clock fast-forwarded; the clock that ticks every
  // cycle fast-forwards none).
  const qacc::HwRender r = qacc::renderHwCycle(scene, cfg, 1, qacc::MachineClock::Repeating);
  const qacc::HwRender c = qacc::renderHwCycle(scene, cfg, 1, qacc::MachineClock::EveryCycle);
  if (c.stats.fast_forwarded != 0 || b.stats.simulator_clock != "items") std::abort();
  const std::string expected = c.stats.countsJson();
  if (b.stats.countsJson() != expected || r.stats.countsJson() != expected || !(b.fb.color.data == c.fb.color.data) ||
      !(r.fb.color.data == c.fb.color.data))
    std::abort();
  // The item clock with the hierarchical Z unit (4x4 tiles: lookups that reject at this size),
  // against ticking every cycle; the unit rejects only pixels that would fail the Z test, so
  // the image is the one without it.
  qacc::HwConfig hizCfg;
  hizCfg.hierarchical_z = true;
  hizCfg.hiz_tile_size = 4;
  const qacc::HwRender hi = qacc::renderHwCycle(scene, hizCfg, 1, qacc::MachineClock::Items);
  const qacc::HwRender hc = qacc::renderHwCycle(scene, hizCfg, 1, qacc::MachineClock::EveryCycle);
  if (hi.stats.simulator_clock != "items" || hi.stats.countsJson() != hc.stats.countsJson() ||
      !(hi.fb.color.data == hc.fb.color.data) || !(hi.fb.color.data == c.fb.color.data) || hi.fb.object != c.fb.object)
    std::abort();
  // A render that takes the setups, the pixel trace and the frame of the render before it (the
  // same scene and datapath under other timing keys: engines/datapath_reuse.h) must count and
  // draw what a render from scratch does.
  qacc::DatapathReuse reuse;
  reuse.setScene("fuzz", "fuzz");
  qacc::renderHwCycle(scene, cfg, 1, qacc::MachineClock::Items, &reuse);
  qacc::HwConfig timing = cfg;
  timing.pipelines = 3;
  timing.zbuffer_banks = 6;
  timing.clip_evaluators = 1;
  timing.pixel_fifo_depth = 2;
  timing.shading_cycles_per_pixel = 2;
  const qacc::HwRender ru = qacc::renderHwCycle(scene, timing, 1, qacc::MachineClock::Items, &reuse);
  const qacc::HwRender rf = qacc::renderHwCycle(scene, timing, 1);
  if (ru.stats.reused != "setup, pixel trace, frame" || ru.stats.countsJson() != rf.stats.countsJson() ||
      !(ru.fb.color.data == rf.fb.color.data) || ru.fb.object != rf.fb.object)
    std::abort();
  tessellateLikeFacets(scene);
  ++counts.drawn;
  return 0;
}

// JSON-aware mutations (fuzz/json_mutator.h), with the format's words from the dictionary.
extern "C" std::size_t LLVMFuzzerCustomMutator(std::uint8_t* data, std::size_t size, std::size_t max_size,
                                               unsigned int seed) {
  static const std::vector<std::string> words = qacc::fuzz::dictionaryWords(QACC_SOURCE_DIR "/fuzz/scene.dict");
  return qacc::fuzz::mutateJson(data, size, max_size, seed, words);
}
