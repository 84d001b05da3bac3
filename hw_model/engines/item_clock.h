// The item clock: hw-cycle's main pass timed item by item instead of cycle by cycle. The
// timed units (timing/) define the machine; where the item clock applies, each primitive's
// and each pixel's cycles follow from its predecessors' by the units' own rules, so the
// frame is computed in one pass over the items, in issue order, without ticking the units:
//  - a pixel pipeline and the Z unit accept whatever their outputs do (their stages are
//    unbounded), so a pixel's accept is max(arrival, the previous pixel's accept + that
//    pixel's clip passes), and a full channel only delays its sender to the cycle after the
//    item `capacity` places ahead of it was received (channels count their occupancy at the
//    start of the cycle: channel.h);
//  - with `zbuffer_banks` a multiple of `pipelines`, each Z port has its own banks (pixel
//    (x, y) goes to pipeline (x + y) mod P and bank (x + y) mod B), so a request waits only
//    for its own port's earlier requests and its bank, and the round-robin priority decides
//    nothing; every pixel's requests reach the Z-buffer in the same order as in the ticked
//    machine, so the depth tests give the same winners;
//  - every event of an item is later than the cycle the traversal issued it in, so the
//    units' counters (busy / stall / idle: a cycle is busy when the unit changed anything,
//    else a stall when it waited on an output, else busy when it holds work) are counted
//    from per-cycle flags (a bit a cycle each) behind the traversal.
//  - with the hierarchical Z unit, a block's lookup happens in the cycle traversal reaches
//    the block, and sees the Z writes due by then (issued update_latency cycles before or
//    earlier): every such write comes from a pixel issued earlier, already timed, so each Z
//    port's writes wait in a queue in due order, and a lookup applies those due in the order
//    they reach the tile memory (by due cycle, then by the Z unit's round-robin order within
//    the cycle they were issued in).
// One pass over the items: it ends on any input, and needs no deadlock limit (the clock that
// ticks every cycle reports a million unchanged cycles in a row as a deadlock, so a frame
// with a longer wait, such as a descriptor of hundreds of clip planes on the slowest bus,
// has cycles under this clock and none under that one).
// Applies with banks shared by no two ports; elsewhere (and in the CSG pass) the engine
// ticks the units (machine_run.h).
// The tests compare every counter with the clock that ticks every cycle, on every shipped
// scene and configuration and under random timings (test_hw_engines.cpp).
#pragma once
#include <cstdint>
#include <vector>

#include "hw_model/config/hw_config.h"
#include "hw_model/datapath/primitive_setup.h"
#include "hw_model/datapath/zbuffer_memory.h"
#include "hw_model/engines/pixel_trace.h"
#include "hw_model/report/hierarchical_z_counters.h"
#include "hw_model/report/hw_stats.h"

namespace qacc {

// Whether the item clock gives the ticked machine's cycles and counters for this
// configuration (zbuffer_banks a multiple of pipelines).
bool itemClockApplies(const HwConfig& cfg);

struct ItemClockRun {
  std::uint64_t cycles = 0;
  // The units' counters in the wiring's order (cycle_engine.cpp): host interface, setup,
  // traversal, the P pixel pipelines, the Z unit, the hierarchical Z unit (when configured),
  // the P shading units.
  std::vector<UnitStats> units;
  std::uint64_t delivered = 0;  // pixels the shading units delivered
  std::uint64_t culled = 0;     // primitives the setup unit dropped (culled at the host)
  HierarchicalZCounters hiz;    // the hierarchical Z unit's (enabled with the unit)
};

// The main pass of `setups` (the csg objects' leaves not visible), its pixels' results from
// `trace` (filled, or being filled ahead: PixelTrace::awaitPrimitive), its winners left in
// `zb`, its pixel counters added to `px`.
ItemClockRun runItemClock(const HwConfig& cfg, const std::vector<PrimitiveSetup>& setups, const PixelTrace& trace,
                          ZBufferMemory& zb, PixelCounters& px);

}  // namespace qacc
