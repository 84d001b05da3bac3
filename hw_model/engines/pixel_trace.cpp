#include "hw_model/engines/pixel_trace.h"

#include <omp.h>

#include <algorithm>
#include <chrono>
#include <stdexcept>
#include <thread>

#include "hw_model/datapath/pixel_datapath.h"

namespace qacc {

PixelTrace::Fill::Fill(PixelTrace& tr, const std::vector<PrimitiveSetup>& s, const HwConfig& c)
    : setups(s), cfg(c), pixels(tr.pixels.data()), first(tr.first.data()), rows(tr.rows.data()),
      passes(tr.passes.data()), ready(new std::atomic<bool>[s.size()]), overflow(s.size()) {
  for (std::size_t i = 0; i < s.size(); ++i) ready[i].store(false, std::memory_order_relaxed);
}
PixelTrace::Fill::~Fill() = default;

PixelTrace PixelTrace::plan(const std::vector<PrimitiveSetup>& setups, const HwConfig& cfg, int threads) {
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
  tr.fill_ = std::make_unique<Fill>(tr, setups, cfg);
  return tr;
}

// The datapath along primitive i's spans, in pieces of up to kChunk pixels.
void PixelTrace::Fill::fillPrimitive(std::size_t i, PixelDatapath& pp) {
  const PrimitiveSetup& s = setups[i];
  if (!s.visible) return;
  constexpr int kChunk = 64;
  PixelOutcome outcomes[kChunk];
  TracedPixel* out = pixels + first[i];
  pp.load(s);
  passes[i] = pp.clipPasses();
  for (const RowSpans& r : rows[i]) {
    const int y = r.y;
    const Span* sp = r.s;
    for (int k = 0; k < r.n; ++k)
      for (int xa = sp[k].x0; xa < sp[k].x1; xa += kChunk) {
        const int m = std::min(kChunk, sp[k].x1 - xa);
        pp.evaluateSpan(xa - s.x0, y - s.y0, m, outcomes, overflow[i]);
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

bool PixelTrace::Fill::fillNext(PixelDatapath& pp) {
  const std::size_t i = next.fetch_add(1, std::memory_order_relaxed);
  if (i >= setups.size()) return false;
  fillPrimitive(i, pp);
  ready[i].store(true, std::memory_order_release);
  return true;
}

void PixelTrace::fillAhead() {
  PixelDatapath pp(fill_->cfg);  // one per filling thread, loaded with each primitive it takes
  while (fill_->fillNext(pp)) {
  }
}

void PixelTrace::finishFill() {
  for (const OverflowCounters& o : fill_->overflow) overflow.add(o);
  waitSeconds_ = fill_->waitSeconds;
  fill_.reset();  // every primitive is published: awaitPrimitive has nothing left to wait for
}

void PixelTrace::retime(const std::vector<PrimitiveSetup>& setups, const HwConfig& cfg) {
  if (fill_) throw std::logic_error("PixelTrace::retime: the trace is still being filled");
  for (std::size_t i = 0; i < setups.size(); ++i)
    if (setups[i].visible) passes[i] = PixelDatapath::clipPassesOf(setups[i], cfg);
}

void PixelTrace::waitFor(int prim) const {
  const auto t0 = std::chrono::steady_clock::now();
  Fill& f = *fill_;
  // Fill the primitives no filler has taken yet (the fillers may be behind the loop); once
  // every primitive is taken, wait for the one being filled.
  if (!f.readerDatapath) f.readerDatapath = std::make_unique<PixelDatapath>(f.cfg);
  while (!f.ready[std::size_t(prim)].load(std::memory_order_acquire))
    if (!f.fillNext(*f.readerDatapath)) std::this_thread::yield();
  f.waitSeconds += std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
}

PixelTrace PixelTrace::build(const std::vector<PrimitiveSetup>& setups, const HwConfig& cfg, int threads) {
  PixelTrace tr = plan(setups, cfg, threads);
  const int nt = threads > 0 ? threads : omp_get_max_threads();
#pragma omp parallel num_threads(nt)
  tr.fillAhead();
  tr.finishFill();
  return tr;
}

}  // namespace qacc
