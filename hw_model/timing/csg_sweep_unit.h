// CsgSweepUnit: the per-pixel tree evaluation of hw-cycle's CSG pass
// (engines/csg_cycle_pass.h). One sweeper per pipeline, over the lists that pipeline's
// port filled: for each pixel of a completed job with a non-empty list, it reads the
// list's ends in depth order, one end per cycle, evaluating the tree (the sweep of
// raster/reference/csg_hit.h; the winners come from the job's record), and sends a winner
// to its Z-buffer port as a visible point. When every sweeper has finished the job, its
// tile list buffer is freed for the issue unit.
#pragma once
#include <vector>

#include "hw_model/config/hw_config.h"
#include "hw_model/engines/csg_tile.h"
#include "hw_model/timing/channel.h"
#include "hw_model/timing/tokens.h"
#include "hw_model/timing/traversal_unit.h"
#include "hw_model/timing/unit.h"

namespace qacc {

class CsgSweepUnit final : public Unit {
 public:
  // The pixels' pipelines: the traversal's interleave, which the list ports follow.
  using Params = TraversalUnit::Params;

  CsgSweepUnit(const Params& p, const std::vector<CsgJob>& jobs, Channel<int>& in, Channel<int>& bufferFreed,
               std::vector<Channel<PointToken>*> out)
      : Unit("csg_sweep"), p_(p), jobs_(jobs), in_(in), freed_(bufferFreed), out_(std::move(out)),
        queue_(out_.size()), pos_(out_.size(), 0), current_(out_.size(), -1), doneAt_(out_.size(), 0) {}
  bool tick(std::uint64_t now);
  std::uint64_t nextEvent() const;
  bool holdsWork() const { return job_ >= 0; }

 private:
  Params p_;
  const std::vector<CsgJob>& jobs_;
  Channel<int>& in_;
  Channel<int>& freed_;
  std::vector<Channel<PointToken>*> out_;
  int job_ = -1;
  std::vector<std::vector<int>> queue_;  // per sweeper: the job's swept pixels it owns
  std::vector<std::size_t> pos_;
  std::vector<int> current_;             // per sweeper: the pixel being swept (-1: none)
  std::vector<std::uint64_t> doneAt_;    // ... and the cycle its sweep ends
};

}  // namespace qacc
