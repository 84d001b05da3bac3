// HierarchicalZUnit: the timing of the optional hierarchical Z unit (HwConfig::
// hierarchical_z; the tile memory and the rejection test are datapath/
// hierarchical_z_memory.h). The traversal unit looks up the tile of each block of a span (the
// span's pixels inside one hiz_tile_size² tile) before issuing it: a rejected block is
// skipped, its pixels never enter a pixel pipeline, and the lookup holds traversal for
// `lookup_cycles`; an accepted block costs no cycle (the lookup of the next block overlaps
// the issue of the current one). The Z-buffer unit reports every write; the tile memory
// sees it `update_latency` cycles later (the Z unit's read latency, then one cycle for the
// tile record's read-modify-write). A lookup at cycle t sees exactly the writes due by t,
// whatever the order in which the units tick (a write of cycle t is due at t + 1 or later).
// Stale bounds are conservative: stored depths only move nearer.
#pragma once
#include <algorithm>
#include <cstdint>

#include "hw_model/config/hw_config.h"
#include "hw_model/datapath/hierarchical_z_memory.h"
#include "hw_model/report/hierarchical_z_counters.h"
#include "hw_model/timing/delay_queue.h"
#include "hw_model/timing/unit.h"

namespace qacc {

class HierarchicalZUnit final : public Unit {
 public:
  struct Params {
    int tile_size = 16;
    int lookup_cycles = 1;   // cycles a rejected block holds traversal
    int update_latency = 3;  // cycles from a Z write to the tile memory
    static Params from(const HwConfig& cfg) { return {cfg.hiz_tile_size, 1, cfg.zbuffer_read_latency + 1}; }
  };

  HierarchicalZUnit(const Params& p, const HwConfig& cfg, int width, int height)
      : Unit("hierarchical_z"), p_(p), memory_(cfg, 0, 0, width, height) {}
  // Does the block of a span starting at pixel (x, y) fail the Z test everywhere, for a
  // primitive whose depth floor stores as storedFloor? (A lookup, at cycle `now`.)
  bool rejects(std::uint64_t now, int x, int y, std::uint32_t storedFloor);
  // A Z-buffer write at cycle `now` (a pixel that passed the Z test).
  void noteWrite(std::uint64_t now, int x, int y, std::uint32_t stored) {
    pending_.push_back({now + std::uint64_t(p_.update_latency), x, y, stored});
    ++updates_;
  }
  bool tick(std::uint64_t now) {
    applyDue(now);
    // Busy in a cycle with a lookup or a tile update (the traversal unit ticks first).
    if (lastActive_ == now) countBusy();
    else countIdle();
    return false;  // the tile memory's state moves no token
  }
  bool holdsWork() const { return false; }  // nothing waits on a tile update
  // The next tile update due: its tick writes the tile memory and counts busy.
  std::uint64_t nextEvent() const { return pending_.empty() ? kNoEvent : pending_.front().due; }
  // Unchanged: the next tile update due (lookups come from traversal, which reports them).
  std::uint64_t nextChange(std::uint64_t now) const {
    return pending_.empty() ? kNoEvent : std::max(now, pending_.front().due);
  }
  const Params& params() const { return p_; }
  HierarchicalZCounters counters;

 private:
  struct Update {
    std::uint64_t due;
    int x, y;
    std::uint32_t stored;
  };
  // The tile memory takes the writes due by `now`.
  void applyDue(std::uint64_t now) {
    while (!pending_.empty() && pending_.front().due <= now) {
      const Update& u = pending_.front();
      memory_.write(u.x, u.y, u.stored);
      pending_.pop_front();
      lastActive_ = now;
    }
  }
  Params p_;
  HierarchicalZMemory memory_;
  DelayQueue<Update> pending_;
  std::uint64_t updates_ = 0, lastActive_ = ~std::uint64_t(0);
};

}  // namespace qacc
