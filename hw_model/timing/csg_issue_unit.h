// CsgIssueUnit: the traversal of hw-cycle's CSG pass (engines/csg_cycle_pass.h). Job by
// job (a csg object in one tile, in tile order, csg objects in scene order), it issues
// every leaf's pixels over its box ∩ tile, in the job's order, to the P pipelines
// screen-interleaved like the traversal unit (pipeline (x + y) mod P, up to P pixels per
// cycle, a new row on a new cycle), then one end marker per pipeline. A job starts only
// when a tile list buffer is free (kCsgListBuffers; the sweep unit frees one per job done).
// With tile pruning (csg_tile_pruning) a job first spends its box tester's cycles
// (CsgJob::testCycles, one per node of the tree); the tester works one job ahead (two flag
// buffers), so a job's tests overlap the issue of the previous one; a job whose pruned tree
// is empty ends after its tests, without a list buffer.
#pragma once
#include <vector>

#include "hw_model/config/hw_config.h"
#include "hw_model/engines/csg_tile.h"
#include "hw_model/timing/channel.h"
#include "hw_model/timing/csg_tokens.h"
#include "hw_model/timing/traversal_unit.h"
#include "hw_model/timing/unit.h"

namespace qacc {

class CsgIssueUnit final : public Unit {
 public:
  struct Params {
    int pipelines = 2;
    int list_buffers = kCsgListBuffers;
    static Params from(const HwConfig& cfg) { return {cfg.pipelines, kCsgListBuffers}; }
    int pipelineOf(int x, int y) const { return TraversalUnit::Params{pipelines}.pipelineOf(x, y); }
  };

  CsgIssueUnit(const Params& p, const std::vector<CsgJob>& jobs, Channel<int>& bufferFreed,
               std::vector<Channel<CsgToken>*> out)
      : Unit("csg_issue"), p_(p), jobs_(jobs), freed_(bufferFreed), out_(std::move(out)), free_(p.list_buffers) {}
  bool tick(std::uint64_t now);
  std::uint64_t nextEvent() const;
  bool holdsWork() const { return job_ >= 0 || next_ < jobs_.size(); }

 private:
  Params p_;
  const std::vector<CsgJob>& jobs_;
  Channel<int>& freed_;
  std::vector<Channel<CsgToken>*> out_;
  int free_;
  int job_ = -1;          // the job being issued
  std::size_t next_ = 0;  // the next job to start
  std::size_t k_ = 0;     // its next pixel
  std::uint64_t markers_ = 0;  // pipelines that have the job's end marker
  std::size_t testedJob_ = std::size_t(-1);  // the job the box tester works or worked on
  std::uint64_t testDone_ = 0;               // the cycle its tests end
  std::uint64_t now_ = 0;
  bool testing() const { return next_ < jobs_.size() && testedJob_ == next_ && testDone_ > now_; }
};

}  // namespace qacc
