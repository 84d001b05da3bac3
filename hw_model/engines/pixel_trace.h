// PixelTrace: the pixel pipelines' datapath results for every pixel the traversal issues,
// per primitive in traversal order (rows top to bottom, spans left to right), computed by
// the shared PixelDatapath arithmetic (forward differences along each span, exactly the
// functional engine's code) in parallel before the cycle-level timing loop runs.
//
// The cycle engine is functional-first, timing-directed: the arithmetic of a pixel does
// not depend on when it is computed, only on the primitive and the pixel, so it is done
// once, as fast as the host allows (the design's "the software may compute the same bits
// faster"); the timing units then move tokens that carry these results through FIFOs,
// banks and latencies cycle by cycle. What depends on timing and order — the Z test
// against the banked buffer, what reaches shading, stalls — is simulated in the loop.
#pragma once
#include <cstdint>
#include <type_traits>
#include <vector>

#include "hw_model/config/hw_config.h"
#include "hw_model/datapath/overflow_counters.h"
#include "hw_model/datapath/primitive_setup.h"
#include "hw_model/datapath/span_solver.h"
#include "raster/image/default_init_allocator.h"

namespace qacc {

// Trivially constructible, without default values: PixelTrace::build sizes the trace
// without touching it (UninitVector) and its parallel pass writes every field of every
// pixel, first touching the pages in the threads that fill them. 8 bytes (bit-fields): the
// clip passes, the same for every pixel of a primitive, are kept per primitive
// (PixelTrace::clipPasses), so molecule's trace at 1920x1080 takes 10 MB, not 20.
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
  // traversal order), so that the trace — tens of megabytes at 1920x1080 — is one block,
  // returned whole to the system when the trace is released (and, like a frame buffer,
  // backed by huge pages where the system offers them: raster/image/default_init_allocator.h).
  UninitVector<TracedPixel> pixels;
  std::vector<std::size_t> first;           // indexed by primitive, one past the last at the end
  std::vector<std::vector<RowSpans>> rows;  // indexed by primitive: its non-empty rows
  std::vector<int> passes;                  // indexed by primitive: PixelDatapath::clipPasses
  OverflowCounters overflow;                // datapath overflows of all pixels
  // The k-th pixel the traversal issues for primitive `prim`.
  const TracedPixel& pixel(int prim, int k) const { return pixels[first[std::size_t(prim)] + std::size_t(k)]; }
  // The clip-unit passes of each of primitive `prim`'s pixels.
  int clipPasses(int prim) const { return passes[std::size_t(prim)]; }
  static PixelTrace build(const std::vector<PrimitiveSetup>& setups, const HwConfig& cfg, int threads);
};

}  // namespace qacc
