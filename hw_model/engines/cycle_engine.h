// Cycle-level accelerator engine (`--engine hw-cycle`): every unit (host interface,
// setup, traversal, P pixel pipelines, Z-buffer, P shading units) ticks once per modeled
// cycle; units talk through bounded FIFOs committed at the end of each cycle (two-phase,
// so tick order does not matter); a full FIFO stalls its producer; the frame ends when
// everything has drained. Cycles in which nothing moves are skipped in one step
// (fast-forward to the next timed event). The arithmetic is the functional engine's
// (SetupUnit::run, PixelPipeline, ZBufferUnit::testAndWrite, ShadingUnit::shade of the
// final winners once drained): the image is bit-identical to `hw`; this engine only adds
// time.
#pragma once
#include "hw_model/engines/functional_engine.h"

namespace qacc {

HwRender renderHwCycle(const Scene& scene, const HwConfig& cfg, int threads = 0);

}  // namespace qacc
