// hw-cycle's CSG pass (docs/CSG.md): after the other primitives have drained, the csg
// objects are drawn by timed units wired here — CsgIssueUnit (leaf pixels per job, to the
// P pipelines) -> P pixel pipelines in interval mode (CsgIntervalPipelineUnit) ->
// CsgListUnit (one insertion per interval per port into the bounded lists of a tile list
// buffer) -> CsgSweepUnit (one list end per cycle per sweeper) -> the Z-buffer unit (equal
// stored depths to the primitive earlier in scene order, so the image equals hw's) -> the
// P shading units. The work of each job (a csg object in one tile) and its results come
// from drawCsgTile (engines/csg_tile.h), computed beforehand in parallel: functional
// first, timing directed, like the pixel trace.
#pragma once
#include "hw_model/config/hw_config.h"
#include "hw_model/datapath/zbuffer_memory.h"
#include "hw_model/engines/csg_tile.h"
#include "hw_model/engines/frame_setup.h"
#include "hw_model/engines/machine_clock.h"
#include "hw_model/report/hw_stats.h"

namespace qacc {

// Draws every csg object of the frame into the frame-sized `zb`; adds the pass's cycles
// to stats.cycles and stats.csg.cycles, its counters to stats.pixels and stats.csg, and
// its units' cycles to stats.units (the pipelines, Z-buffer and shading under their own
// names; every unit idle while the other part of the frame runs). `clock`: as renderHwCycle's.
void runCsgCyclePass(const CsgFrame& csg, const FrameSetup& fs, const HwConfig& cfg, int width, int height,
                     ZBufferMemory& zb, int threads, MachineClock clock, HwStats& stats);

}  // namespace qacc
