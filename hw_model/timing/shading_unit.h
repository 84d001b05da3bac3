// ShadingUnit: timing of one shading unit (the arithmetic is datapath/shading_arithmetic.h).
// Pipelined: accepts a pixel that passed the Z test every shading_cycles_per_pixel cycles,
// delivers its colour shading_latency cycles later. Colours are a pure function of the
// Z-buffer's final winners, so the cycle engine resolves the frame once the pipeline has
// drained (engines/frame_resolve.h); the unit counts what it delivered, which the
// functional engine cannot know.
#pragma once
#include <string>

#include "hw_model/config/hw_config.h"
#include "hw_model/timing/channel.h"
#include "hw_model/timing/pipeline.h"
#include "hw_model/timing/tokens.h"
#include "hw_model/timing/unit.h"

namespace qacc {

class ShadingUnit final : public Unit {
 public:
  struct Params {
    int cycles_per_pixel = 1;  // initiation interval
    int latency = 12;
    static Params from(const HwConfig& cfg) { return {cfg.shading_cycles_per_pixel, cfg.shading_latency}; }
  };

  ShadingUnit(const std::string& name, const Params& p, ChannelRegistry& wires, Channel<PointToken>& in)
      : Unit(name), p_(p), in_(in), stages_(wires, std::uint64_t(p.latency)) {}
  bool tick(std::uint64_t now);
  std::uint64_t nextEvent() const { return stages_.nextEvent(in_.ready()); }
  std::uint64_t nextChange(std::uint64_t now) const { return stages_.nextChange(now, in_.nextArrival()); }
  bool holdsWork() const { return stages_.holdsWork(); }
  std::uint64_t delivered() const { return delivered_; }

 private:
  // A pixel in the stages: its colour is the resolve's (a pure function of the final
  // winners), so the stages keep only when each pixel finishes.
  struct InFlight {};
  Params p_;
  Channel<PointToken>& in_;
  Pipeline<InFlight> stages_;
  std::uint64_t delivered_ = 0;
};

inline bool ShadingUnit::tick(std::uint64_t now) {
  (void)now;
  bool changed = false;
  while (stages_.done()) {
    ++delivered_;
    stages_.retire();
    changed = true;
  }
  if (stages_.canAccept() && in_.ready()) {
    stages_.accept({}, std::uint64_t(p_.cycles_per_pixel));
    in_.receive();
    countItem();
    changed = true;
  }
  if (changed || stages_.holdsWork()) countBusy();
  else countIdle();
  return changed;
}

}  // namespace qacc
