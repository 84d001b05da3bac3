// CsgListUnit: the list memory's insertion ports (hw-cycle's CSG pass,
// engines/csg_cycle_pass.h). Pixels are interleaved over the P pipelines as they are over
// the Z-buffer's, so each pipeline owns the lists of its pixels and has its own port:
// inserting an interval into a pixel's sorted, bounded list (datapath/csg_interval_list.h)
// is one read-modify-write of the list, one cycle per interval; a pixel that gave no
// interval takes its cycle in the port and writes nothing. A job's lists are complete
// when every port has taken the job's end marker (after its last insertion); the unit
// then hands the job to the sweep unit, jobs in order.
#pragma once
#include <vector>

#include "hw_model/engines/csg_tile.h"
#include "hw_model/timing/channel.h"
#include "hw_model/timing/csg_tokens.h"
#include "hw_model/timing/unit.h"

namespace qacc {

class CsgListUnit final : public Unit {
 public:
  CsgListUnit(const std::vector<CsgJob>& jobs, std::vector<Channel<CsgToken>*> in, Channel<int>& toSweep)
      : Unit("csg_list"), jobs_(jobs), in_(std::move(in)), out_(toSweep), busyUntil_(in_.size(), 0),
        markers_(jobs.size(), 0) {}
  bool tick(std::uint64_t now);
  std::uint64_t nextEvent() const;
  bool holdsWork() const;

 private:
  const std::vector<CsgJob>& jobs_;
  std::vector<Channel<CsgToken>*> in_;
  Channel<int>& out_;
  std::vector<std::uint64_t> busyUntil_;  // per port: the cycle its current insertions end
  std::vector<int> markers_;              // per job: ports that took its end marker
  std::size_t nextJob_ = 0;               // the next job to hand to the sweep unit
  std::uint64_t now_ = 0;
};

}  // namespace qacc
