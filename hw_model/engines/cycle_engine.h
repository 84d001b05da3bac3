// Cycle-level accelerator engine (`--engine hw-cycle`): every timed unit (timing/: host
// interface, setup, traversal, P pixel pipelines, Z-buffer, P shading units) ticks once per
// modeled cycle; units talk through bounded channels that carry a latency, committed at the
// end of each cycle by one registry (two-phase, so tick order does not matter); a full
// channel stalls its producer; the frame ends when everything has drained. Cycles that
// cannot differ from the one before (nothing moves before the next timed event, or a unit
// only waits on a full channel) are not ticked one by one: that tick's counts are repeated. The
// arithmetic is the functional engine's (datapath/: setup arithmetic, pixel datapath via
// the pixel trace, Z-buffer memory, shading of the final winners once drained): the image
// is bit-identical to `hw`; this engine only adds time.
#pragma once
#include "hw_model/engines/datapath_reuse.h"
#include "hw_model/engines/functional_engine.h"
#include "hw_model/engines/machine_clock.h"

namespace qacc {

// `clock`: MachineClock::EveryCycle ticks every cycle (for tests: the same counts, slower).
// `reuse`: the setups, pixel trace and frame of an earlier render of the same scene under the
// same datapath are taken from it, and this render's are kept in it (datapath_reuse.h).
HwRender renderHwCycle(const Scene& scene, const HwConfig& cfg, int threads = 0,
                       MachineClock clock = MachineClock::Items, DatapathReuse* reuse = nullptr);

}  // namespace qacc
