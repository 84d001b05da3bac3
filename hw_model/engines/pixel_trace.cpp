#include "hw_model/engines/pixel_trace.h"

#include <omp.h>

#include <algorithm>
#include <chrono>
#include <thread>

#include "hw_model/datapath/pixel_datapath.h"

namespace qacc {

PixelTrace PixelTrace::plan(const std::vector<PrimitiveSetup>& setups, int threads) {
  PixelTrace tr;
  const int n = int(setups.size());
  tr.rows.resize(std::size_t(n));
  tr.first.assign(std::size_t(n) + 1, 0);
  tr.passes.assign(std::size_t(n), 1);
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
  tr.fill_ = std::make_unique<Fill>(std::size_t(n));
  return tr;
}

// The datapath along primitive i's spans, in pieces of up to kChunk pixels.
void PixelTrace::fillPrimitive(std::size_t i, const PrimitiveSetup& s, PixelDatapath& pp, OverflowCounters& ovf) {
  if (!s.visible) return;
  constexpr int kChunk = 64;
  PixelOutcome outcomes[kChunk];
  TracedPixel* out = pixels.data() + first[i];
  pp.load(s);
  passes[i] = pp.clipPasses();
  for (const RowSpans& r : rows[i]) {
    const int y = r.y;
    const Span* sp = r.s;
    for (int k = 0; k < r.n; ++k)
      for (int xa = sp[k].x0; xa < sp[k].x1; xa += kChunk) {
        const int m = std::min(kChunk, sp[k].x1 - xa);
        pp.evaluateSpan(xa - s.x0, y - s.y0, m, outcomes, ovf);
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

void PixelTrace::fillAhead(const std::vector<PrimitiveSetup>& setups, const HwConfig& cfg) {
  PixelDatapath pp(cfg);  // one per filling thread, loaded with each primitive it takes
  Fill& f = *fill_;
  for (;;) {
    const std::size_t i = f.next.fetch_add(1, std::memory_order_relaxed);
    if (i >= setups.size()) return;
    fillPrimitive(i, setups[i], pp, f.overflow[i]);
    f.ready[i].store(true, std::memory_order_release);
  }
}

void PixelTrace::finishFill() {
  for (const OverflowCounters& o : fill_->overflow) overflow.add(o);
}

void PixelTrace::waitFor(int prim) const {
  const auto t0 = std::chrono::steady_clock::now();
  while (!fill_->ready[std::size_t(prim)].load(std::memory_order_acquire)) std::this_thread::yield();
  fill_->waitSeconds += std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
}

PixelTrace PixelTrace::build(const std::vector<PrimitiveSetup>& setups, const HwConfig& cfg, int threads) {
  PixelTrace tr = plan(setups, threads);
  const int nt = threads > 0 ? threads : omp_get_max_threads();
#pragma omp parallel num_threads(nt)
  tr.fillAhead(setups, cfg);
  tr.finishFill();
  return tr;
}

}  // namespace qacc
