#include "tools/compare/quadric_runs.h"

#include <cstdio>

#include "raster/reference/reference_renderer.h"
#include "tools/compare/stopwatch.h"
#include "tools/engines/hw_engine.h"

namespace qacc::compare {

QuadricRuns renderQuadrics(const ComparePlan& plan, int threads) {
  const Scene& scene = plan.scene;
  QuadricRuns q;
  std::fprintf(stderr, "compare %s: %zu primitives, %dx%d\n", scene.name.c_str(), scene.primitives.size(), scene.width,
               scene.height);
  auto t0 = Clock::now();
  q.ref = renderReference(scene, threads);
  q.ref_ms = msSince(t0);
  std::fprintf(stderr, "  reference %.1f ms\n", q.ref_ms);

  Row& hw = q.hw;
  hw.engine = "hw";
  hw.primitives = scene.primitives.size();
  HwStats st;
  t0 = Clock::now();
  hw.fb = renderWithHwEngine("hw", scene, plan.cfg, threads, st);
  hw.host_ms = msSince(t0);
  HwStats stc;
  const FrameBuffer hwc = renderWithHwEngine("hw-cycle", scene, plan.cfg, threads, stc);
  hw.cycles = stc.cycles;
  hw.modeled_ms = stc.frameSeconds() * 1e3;
  hw.m = measure(q.ref, hw.fb, scene.camera, plan.zbits);
  q.identical = hwc.color.data == hw.fb.color.data && hwc.object == hw.fb.object;
  std::fprintf(stderr, "  hw %.1f ms, hw-cycle %llu cycles (%s)\n", hw.host_ms, (unsigned long long)hw.cycles,
               q.identical ? "images bit-identical" : "IMAGES DIFFER");
  return q;
}

}  // namespace qacc::compare
