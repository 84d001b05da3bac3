// PixelPipelineUnit: timing of one pixel pipeline (interpolators, square root, depth,
// clip, caps; PixelPipeline holds the arithmetic, whose result for each issued pixel the
// unit takes from the PixelTrace). Fully pipelined: accepts one pixel per cycle, or one
// every `clip passes` cycles when a primitive has more planes than the K clip evaluators;
// results leave in order after pixelPipelineLatency() cycles; pixels with a visible point
// go on to the Z-buffer, the others retire.
#pragma once
#include <vector>

#include "hw_model/timing/delay_queue.h"
#include "hw_model/timing/fifo.h"
#include "hw_model/config/hw_config.h"
#include "hw_model/engines/frame_setup.h"
#include "hw_model/engines/pixel_trace.h"
#include "hw_model/timing/traversal_unit.h"
#include "hw_model/timing/unit.h"

namespace qacc {

struct ZRequest {
  int prim = 0;
  int x = 0, y = 0;
  int cap = -1;
  i128 z = 0;
};

class PixelPipelineUnit : public Unit {
 public:
  // `zb` is only a host-side hint: the Z-buffer record of a pixel that will reach the Z
  // unit is prefetched into the host's cache when the pixel enters the pipeline (no
  // modeled effect).
  PixelPipelineUnit(const std::string& name, const PixelTrace& trace, const HwConfig& cfg, Fifo<PixelToken>& in,
                    Fifo<ZRequest>& out, PixelCounters& px, const ZBufferState* zb = nullptr)
      : Unit(name), trace_(trace), in_(in), out_(out), px_(px), latency_(std::uint64_t(cfg.pixelPipelineLatency())),
        zb_(zb) {}
  bool tick(std::uint64_t now) override;
  std::uint64_t nextEvent() const override;
  bool holdsWork() const override { return !inflight_.empty(); }

 private:
  struct InFlight {
    std::uint64_t ready;
    bool hit;
    ZRequest req;
  };
  const PixelTrace& trace_;
  Fifo<PixelToken>& in_;
  Fifo<ZRequest>& out_;
  PixelCounters& px_;
  std::uint64_t latency_;
  DelayQueue<InFlight> inflight_;
  std::uint64_t nextAccept_ = 0;
  const ZBufferState* zb_;
};

}  // namespace qacc
