#include "hw_model/engines/pixel_trace.h"

#include <omp.h>

#include <algorithm>

#include "hw_model/datapath/pixel_datapath.h"

namespace qacc {

PixelTrace PixelTrace::build(const std::vector<PrimitiveSetup>& setups, const HwConfig& cfg, int threads) {
  PixelTrace tr;
  const int n = int(setups.size());
  tr.rows.resize(std::size_t(n));
  tr.first.assign(std::size_t(n) + 1, 0);
  tr.passes.assign(std::size_t(n), 1);
  std::vector<OverflowCounters> ovf(static_cast<std::size_t>(n));
  const int nt = threads > 0 ? threads : omp_get_max_threads();
  // The spans of every row, and each primitive's pixel count.
#pragma omp parallel for schedule(dynamic, 4) num_threads(nt)
  for (int i = 0; i < n; ++i) {
    const PrimitiveSetup& s = setups[std::size_t(i)];
    if (!s.visible) continue;
    std::vector<RowSpans>& rows = tr.rows[std::size_t(i)];
    std::size_t count = 0;
    for (int y = s.y0; y < s.y1; ++y) {
      RowSpans r;
      r.y = y;
      r.n = solveSpans(s, y, s.x0, s.x1, r.s);
      if (r.n == 0) continue;
      for (int k = 0; k < r.n; ++k) count += std::size_t(r.s[k].x1 - r.s[k].x0);
      rows.push_back(r);
    }
    tr.first[std::size_t(i) + 1] = count;
  }
  for (std::size_t i = 0; i < std::size_t(n); ++i) tr.first[i + 1] += tr.first[i];
  tr.pixels.resize(tr.first.back());
  // The datapath along every span: one per thread, loaded with each primitive, its spans
  // evaluated in pieces of up to kChunk pixels.
  constexpr int kChunk = 64;
#pragma omp parallel num_threads(nt)
  {
    PixelDatapath pp(cfg);
    PixelOutcome outcomes[kChunk];
#pragma omp for schedule(dynamic, 4)
    for (int i = 0; i < n; ++i) {
      const PrimitiveSetup& s = setups[std::size_t(i)];
      if (!s.visible) continue;
      TracedPixel* out = tr.pixels.data() + tr.first[std::size_t(i)];
      pp.load(s);
      tr.passes[std::size_t(i)] = pp.clipPasses();
      for (const RowSpans& r : tr.rows[std::size_t(i)]) {
        const int y = r.y;
        const Span* sp = r.s;
        for (int k = 0; k < r.n; ++k)
          for (int xa = sp[k].x0; xa < sp[k].x1; xa += kChunk) {
            const int m = std::min(kChunk, sp[k].x1 - xa);
            pp.evaluateSpan(xa - s.x0, y - s.y0, m, outcomes, ovf[std::size_t(i)]);
            for (int j = 0; j < m; ++j) {
              const PixelOutcome& o = outcomes[j];
              TracedPixel& t = *out++;
              t.z = std::int64_t(o.z);
              t.cap = o.cap;
              t.hit = o.hit;
              t.candidate = o.candidate;
            }
          }
      }
    }
  }
  for (const OverflowCounters& o : ovf) tr.overflow.add(o);
  return tr;
}

}  // namespace qacc
