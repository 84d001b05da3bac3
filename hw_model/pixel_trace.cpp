#include "hw_model/pixel_trace.h"

#include <omp.h>

#include "hw_model/pixel_pipeline.h"
#include "hw_model/traversal_unit.h"

namespace qacc {

PixelTrace PixelTrace::build(const std::vector<PrimitiveSetup>& setups, const HwConfig& cfg, int threads) {
  PixelTrace tr;
  const int n = int(setups.size());
  tr.prims.resize(std::size_t(n));
  std::vector<OverflowCounters> ovf(static_cast<std::size_t>(n));
  const int nt = threads > 0 ? threads : omp_get_max_threads();
#pragma omp parallel for schedule(dynamic, 4) num_threads(nt)
  for (int i = 0; i < n; ++i) {
    const PrimitiveSetup& s = setups[std::size_t(i)];
    if (!s.visible) continue;
    std::vector<TracedPixel>& out = tr.prims[std::size_t(i)];
    std::size_t count = 0;
    for (int y = s.y0; y < s.y1; ++y) {
      Span sp[2];
      const int ns = TraversalUnit::spans(s, y, s.x0, s.x1, sp);
      for (int k = 0; k < ns; ++k) count += std::size_t(sp[k].x1 - sp[k].x0);
    }
    out.reserve(count);
    PixelPipeline pp(s, cfg);
    for (int y = s.y0; y < s.y1; ++y) {
      Span sp[2];
      const int ns = TraversalUnit::spans(s, y, s.x0, s.x1, sp);
      for (int k = 0; k < ns; ++k) {
        pp.startSpan(sp[k].x0 - s.x0, y - s.y0);
        for (int x = sp[k].x0; x < sp[k].x1; ++x) {
          const PixelOutcome o = pp.evaluate(ovf[std::size_t(i)]);
          pp.stepRight();
          TracedPixel t;
          t.z = std::int64_t(o.z);
          t.cap = std::int16_t(o.cap);
          t.hit = o.hit;
          t.candidate = o.candidate;
          t.clipPasses = std::uint16_t(o.clipPasses);
          out.push_back(t);
        }
      }
    }
  }
  for (const OverflowCounters& o : ovf) tr.overflow.add(o);
  return tr;
}

}  // namespace qacc
