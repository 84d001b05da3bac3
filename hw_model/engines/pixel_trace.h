// PixelTrace: the pixel pipelines' datapath results for every pixel the traversal issues,
// per primitive in traversal order (rows top to bottom, spans left to right), computed by
// the shared PixelDatapath arithmetic (forward differences along each span, exactly the
// functional engine's code). The rows' spans are solved first, in parallel; the pixels are
// then filled by the other threads while the cycle-level timing loop runs on one (its
// traversal unit waits for a primitive not yet filled), or before the loop on one thread.
//
// The cycle engine is functional-first, timing-directed: the arithmetic of a pixel does
// not depend on when it is computed, only on the primitive and the pixel, so it is done
// once, as fast as the host allows (the design's "the software may compute the same bits
// faster"); the timing units then move tokens that carry these results through FIFOs,
// banks and latencies cycle by cycle. What depends on timing and order — the Z test
// against the banked buffer, what reaches shading, stalls — is simulated in the loop.
#pragma once
#include <atomic>
#include <cstdint>
#include <memory>
#include <type_traits>
#include <vector>

#include "hw_model/config/hw_config.h"
#include "hw_model/datapath/overflow_counters.h"
#include "hw_model/datapath/primitive_setup.h"
#include "hw_model/datapath/span_solver.h"
#include "raster/image/default_init_allocator.h"

namespace qacc {

// Trivially constructible, without default values: PixelTrace::plan sizes the trace
// without touching it (UninitVector) and fillAhead writes every field of every pixel,
// first touching the pages in the threads that fill them. 8 bytes (bit-fields): the
// clip passes, the same for every pixel of a primitive, are kept per primitive
// (PixelTrace::clipPasses), so molecule's trace at 1920x1080 takes 10 MB, not 20.
class PixelDatapath;

struct TracedPixel {
  std::int64_t z : 46;    // depth, internal format (0 <= z <= 2^depth_frac_bits <= 2^36)
  std::int64_t cap : 16;  // cap plane, -1 for a surface point (a plane index below 2^15, as the datapath's)
  bool hit : 1;           // a visible point survived clipping
  bool candidate : 1;     // a point reached the clip unit
};
static_assert(std::is_trivially_default_constructible_v<TracedPixel>);
static_assert(sizeof(TracedPixel) == 8, "a traced pixel is 8 bytes");

struct RowSpans {  // a row of a primitive with at least one span
  int y = 0, n = 0;
  Span s[2];
};

struct PixelTrace {
  // Every primitive's pixels in one buffer (primitive i's are [first[i], first[i + 1]), in
  // traversal order), so that the trace — tens of megabytes at 1920x1080 — is one block of
  // the main thread's heap, reused whole by the frame buffer when the trace is released (and,
  // like a frame buffer, backed by huge pages where the system offers them:
  // raster/image/default_init_allocator.h).
  UninitVector<TracedPixel> pixels;
  std::vector<std::size_t> first;           // indexed by primitive, one past the last at the end
  std::vector<std::vector<RowSpans>> rows;  // indexed by primitive: its non-empty rows
  std::vector<int> passes;                  // indexed by primitive: PixelDatapath::clipPasses
  OverflowCounters overflow;                // datapath overflows of all pixels
  // The k-th pixel the traversal issues for primitive `prim`.
  const TracedPixel& pixel(int prim, int k) const { return pixels[first[std::size_t(prim)] + std::size_t(k)]; }
  // The clip-unit passes of each of primitive `prim`'s pixels.
  int clipPasses(int prim) const { return passes[std::size_t(prim)]; }

  // The whole trace: plan, then fill every primitive (threads in parallel).
  static PixelTrace build(const std::vector<PrimitiveSetup>& setups, const HwConfig& cfg, int threads);

  // In two steps, so that other threads can fill the pixels while the timing loop reads them
  // (cycle_engine.cpp): plan() solves every row's spans and sizes the block (pixels not
  // touched; `setups` and `cfg` must outlive the fill); fillAhead() is then called by each
  // filling thread, which takes the primitives in order until none is left, and publishes
  // each one filled; the reader calls awaitPrimitive(prim) before it reads a primitive's
  // pixels or clip passes (the traversal unit, as it takes the primitive: a wait of the host,
  // not a modeled cycle), and while it waits it fills the next primitives no filler has taken,
  // so that a fill slower than the loop still runs on every thread. finishFill(), after every
  // filler is done, adds the overflow counters and releases the fill's state. A trace that is only planned, then filled
  // by fillAhead from one thread before the loop, is the same trace.
  static PixelTrace plan(const std::vector<PrimitiveSetup>& setups, const HwConfig& cfg, int threads);
  void fillAhead();
  void finishFill();
  void awaitPrimitive(int prim) const {
    if (fill_ && !fill_->ready[std::size_t(prim)].load(std::memory_order_acquire)) waitFor(prim);
  }
  // A filled trace made ready for a configuration with the same datapath (hwDatapathKey) as
  // the one it was filled under (engines/datapath_reuse.h): its pixels are the same bits, and
  // only the clip passes follow the new clip_evaluators.
  void retime(const std::vector<PrimitiveSetup>& setups, const HwConfig& cfg);
  // The wall time awaitPrimitive spent waiting or filling (the reader's thread), seconds.
  double waitSeconds() const { return fill_ ? fill_->waitSeconds : waitSeconds_; }

 private:
  // The state of a fill in progress, shared by the fillers and the reader. It reaches the
  // trace's arrays through their buffers, which plan() has sized for good (a PixelTrace
  // moved after plan() keeps them), so that the reader's const trace can fill while it waits.
  struct Fill {
    Fill(PixelTrace& tr, const std::vector<PrimitiveSetup>& s, const HwConfig& c);
    ~Fill();
    // Takes the next primitive no thread has taken, fills and publishes it; false when none is left.
    bool fillNext(PixelDatapath& pp);
    // The datapath along primitive i's spans.
    void fillPrimitive(std::size_t i, PixelDatapath& pp);
    const std::vector<PrimitiveSetup>& setups;
    const HwConfig& cfg;
    TracedPixel* const pixels;
    const std::size_t* const first;
    const std::vector<RowSpans>* const rows;
    int* const passes;
    std::unique_ptr<std::atomic<bool>[]> ready;  // primitive i filled and published
    std::atomic<std::size_t> next{0};             // the next primitive a filler takes
    std::vector<OverflowCounters> overflow;       // per primitive (summed in order: any thread count)
    double waitSeconds = 0;                       // the reader's
    std::unique_ptr<PixelDatapath> readerDatapath;  // the reader's, when it fills while it waits
  };
  void waitFor(int prim) const;
  std::unique_ptr<Fill> fill_;  // from plan() to finishFill()
  double waitSeconds_ = 0;      // the finished fill's
};

}  // namespace qacc
