// CsgIntervalPipelineUnit: a pixel pipeline in interval mode (hw-cycle's CSG pass,
// engines/csg_cycle_pass.h): the same interpolators, square root, depth and clip units as
// the visible-point mode (PixelPipelineUnit, whose latency it has), keeping both ends of
// the leaf's intervals (datapath: PixelDatapath::solidIntervals; the results come from
// the job's record). One pixel per cycle, or one every `clip passes` cycles for a leaf
// with more planes than the clip evaluators; in order; every result and end marker goes
// on to the list unit. It is the same hardware as the pipeline of the same name.
#pragma once
#include <string>
#include <vector>

#include "hw_model/config/hw_config.h"
#include "hw_model/engines/csg_tile.h"
#include "hw_model/timing/channel.h"
#include "hw_model/timing/csg_tokens.h"
#include "hw_model/timing/pipeline.h"
#include "hw_model/timing/pixel_pipeline_unit.h"
#include "hw_model/timing/unit.h"

namespace qacc {

class CsgIntervalPipelineUnit final : public Unit {
 public:
  struct Params {
    int latency = 0;
    static Params from(const HwConfig& cfg) { return {PixelPipelineUnit::Params::from(cfg).latency}; }
  };

  CsgIntervalPipelineUnit(const std::string& name, const Params& p, ChannelRegistry& wires,
                          const std::vector<CsgJob>& jobs, Channel<CsgToken>& in, Channel<CsgToken>& out)
      : Unit(name), jobs_(jobs), in_(in), out_(out), stages_(wires, std::uint64_t(p.latency)) {}
  bool tick(std::uint64_t now);
  std::uint64_t nextEvent() const { return stages_.nextEvent(in_.ready()); }
  bool holdsWork() const { return stages_.holdsWork(); }

 private:
  const std::vector<CsgJob>& jobs_;
  Channel<CsgToken>& in_;
  Channel<CsgToken>& out_;
  Pipeline<CsgToken> stages_;
};

}  // namespace qacc
