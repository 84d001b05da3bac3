// PixelPipelineUnit: timing of one pixel pipeline — interpolators, square-root extractor,
// depth unit, clip unit, caps (the arithmetic is datapath/pixel_datapath.h; the unit takes
// each issued pixel's result from the pixel trace). Fully pipelined: accepts one pixel per
// cycle, or one every `clip passes` cycles when a primitive has more planes than the K clip
// evaluators; results leave in order after the pipeline's latency; pixels with a visible
// point go on to the Z-buffer, the others retire.
#pragma once
#include <algorithm>
#include <string>

#include "hw_model/config/hw_config.h"
#include "hw_model/datapath/zbuffer_memory.h"
#include "hw_model/engines/pixel_trace.h"
#include "hw_model/timing/channel.h"
#include "hw_model/timing/pipeline.h"
#include "hw_model/timing/tokens.h"
#include "hw_model/timing/unit.h"

namespace qacc {

class PixelPipelineUnit final : public Unit {
 public:
  struct Params {
    int latency = 0;  // cycles from a pixel's entry to its result
    static Params from(const HwConfig& cfg) {
      // interpolators (1) + square root + depth (divider, or one multiplier stage and a
      // rounding stage for the reciprocal variant) + clip (1) + caps (1)
      const int depth =
          cfg.depth_variant == DepthVariant::Stable ? dividerLatency(cfg.depth_bits, cfg.divider_radix) : 2;
      return {1 + sqrtLatency(cfg.delta_bits, cfg.sqrt_radix) + depth + 1 + 1};
    }
    // The digit-recurrence square root: one step per log2(radix) result bits, plus one.
    static int sqrtLatency(int inputBits, int radix) {
      const int resultBits = (inputBits + 1) / 2;
      const int perStep = radix == 4 ? 2 : 1;
      return (resultBits + perStep - 1) / perStep + 1;
    }
    // The digit-recurrence divider of the stable depth variant, likewise.
    static int dividerLatency(int quotientBits, int radix) {
      const int perStep = radix == 4 ? 2 : 1;
      return (quotientBits + perStep - 1) / perStep + 1;
    }
  };

  // `zb` is only a host-side hint: the Z-buffer record of a pixel that will reach the Z
  // unit is prefetched into the host's cache when the pixel enters the pipeline (no
  // modeled effect).
  PixelPipelineUnit(const std::string& name, const Params& p, ChannelRegistry& wires, const PixelTrace& trace,
                    Channel<PixelToken>& in, Channel<PointToken>& out, PixelCounters& px,
                    const ZBufferMemory* zb = nullptr)
      : Unit(name), trace_(trace), in_(in), out_(out), px_(px), stages_(wires, std::uint64_t(p.latency)), zb_(zb) {}
  bool tick(std::uint64_t now);
  std::uint64_t nextEvent() const { return stages_.nextEvent(in_.ready()); }
  std::uint64_t nextChange(std::uint64_t now) const { return stages_.nextChange(now, in_.nextArrival()); }
  bool holdsWork() const { return stages_.holdsWork(); }

 private:
  struct InFlight {
    bool hit;
    PointToken point;
  };
  const PixelTrace& trace_;
  Channel<PixelToken>& in_;
  Channel<PointToken>& out_;
  PixelCounters& px_;
  Pipeline<InFlight> stages_;
  const ZBufferMemory* zb_;
};

inline bool PixelPipelineUnit::tick(std::uint64_t now) {
  (void)now;
  bool changed = false, stalled = false;
  while (stages_.done()) {
    const InFlight& f = stages_.front();
    if (f.hit) {
      if (!out_.canSend()) {
        stalled = true;
        break;
      }
      out_.send(f.point);
    }
    stages_.retire();
    changed = true;
  }
  if (stages_.canAccept() && in_.ready()) {
    const PixelToken t = in_.front();
    in_.receive();
    const TracedPixel& o = trace_.pixel(t.prim, t.k);
    const int passes = trace_.clipPasses(t.prim);
    ++px_.tested;
    px_.clip_passes += std::uint64_t(passes);
    if (o.hit) {
      if (zb_) __builtin_prefetch(&zb_->px[zb_->index(t.x, t.y)]);
      ++px_.covered;
      px_.caps += o.cap >= 0;
    } else {
      px_.clipped += o.candidate != 0;
    }
    stages_.accept({o.hit, {t.prim, t.x, t.y, int(o.cap), std::int64_t(o.z)}}, std::uint64_t(std::max(1, passes)));
    countItem();
    changed = true;
  }
  countCycle(changed, stalled, stages_.holdsWork());
  return changed;
}

}  // namespace qacc
