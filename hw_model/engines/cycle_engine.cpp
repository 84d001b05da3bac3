#include "hw_model/engines/cycle_engine.h"

#include <omp.h>

#include <algorithm>
#include <chrono>
#include <exception>
#include <limits>
#include <optional>
#include <stdexcept>
#include <string>

#include "hw_model/engines/csg_cycle_pass.h"
#include "hw_model/engines/frame_resolve.h"
#include "hw_model/engines/frame_setup.h"
#include "hw_model/engines/item_clock.h"
#include "hw_model/engines/machine_run.h"
#include "hw_model/engines/pixel_trace.h"
#include "hw_model/timing/channel_registry.h"
#include "hw_model/timing/hierarchical_z_unit.h"
#include "hw_model/timing/host_interface_unit.h"
#include "hw_model/timing/pixel_pipeline_unit.h"
#include "hw_model/timing/setup_unit.h"
#include "hw_model/timing/shading_unit.h"
#include "hw_model/timing/traversal_unit.h"
#include "hw_model/timing/zbuffer_unit.h"

namespace qacc {
namespace {

// The pixel trace and the timed machine over every primitive but the csg objects' leaves,
// leaving its winners in zb. Everything it builds — the trace (every issued pixel's result:
// 10 MB for molecule at 1920x1080), the units, the setups copied for a csg scene — is
// released on return, before the CSG pass and the resolve allocate the frame buffer, except
// the trace when `keep` is given (it is moved there, for DatapathReuse). With `filled` (a
// trace kept from a render under the same datapath: datapath_reuse.h) no trace is computed.
void runTimedPass(const Scene& scene, const HwConfig& cfg, const FrameSetup& fs, const CsgFrame& csg,
                  ZBufferMemory& zb, int nt, MachineClock clock, HwStats& st, PixelTrace* filled, PixelTrace* keep) {
  // The leaves of csg objects do not enter this machine: the CSG pass draws them after it
  // (csg_cycle_pass.h), with the scene-order tie rule, so the image equals hw's.
  FrameSetup timedCopy;
  if (!csg.trees.empty()) {
    timedCopy.setups = fs.setups;
    for (PrimitiveSetup& s : timedCopy.setups)
      if (csg.treeOf(std::size_t(s.index)) >= 0) s.visible = false;
  }
  const std::vector<PrimitiveSetup>& timedSetups = csg.trees.empty() ? fs.setups : timedCopy.setups;
  // So is the pixel arithmetic (functional-first, timing-directed: pixel_trace.h): the rows'
  // spans first, then every pixel, by the other threads while this one runs the timing loop
  // (below), or before it on one thread.
  const auto tr0 = std::chrono::steady_clock::now();
  PixelTrace planned;
  // A kept trace gets this configuration's clip passes (a render that fails after this
  // leaves them in the entry: every render that reuses it retimes it first).
  if (filled) filled->retime(timedSetups, cfg);
  else planned = PixelTrace::plan(timedSetups, cfg, nt);
  PixelTrace& trace = filled ? *filled : planned;
  st.primitives = fs.setups.size();
  for (const PrimitiveSetup& s : fs.setups) {
    st.visible_primitives += s.visible;
    st.culled_at_host += s.culled;
    st.facet_primitives += s.facet && s.visible;
  }

  // The machine, wired in one place: every channel with its capacity, every unit with its
  // parameters. host -> setup -> traversal -> P pixel pipelines -> Z-buffer -> P shading.
  ChannelRegistry wires;
  const std::size_t P = std::size_t(cfg.pipelines);
  auto& hostToSetup = wires.make<PrimitiveToken>(std::size_t(cfg.host_fifo_depth));
  auto& setupToTraversal = wires.make<PrimitiveToken>(std::size_t(cfg.setup_fifo_depth));
  std::vector<Channel<PixelToken>*> toPipeline;
  std::vector<Channel<PointToken>*> toZ, toShading;
  for (std::size_t p = 0; p < P; ++p) {
    toPipeline.push_back(&wires.make<PixelToken>(std::size_t(cfg.pixel_fifo_depth)));
    toZ.push_back(&wires.make<PointToken>(std::size_t(cfg.pixel_fifo_depth)));
    toShading.push_back(&wires.make<PointToken>(std::size_t(cfg.pixel_fifo_depth)));
  }

  // The optional hierarchical Z unit: looked up by traversal, told of writes by the Z unit.
  std::optional<HierarchicalZUnit> hiz;
  std::vector<std::uint32_t> storedFloors;
  if (cfg.hierarchical_z) {
    hiz.emplace(HierarchicalZUnit::Params::from(cfg), cfg, scene.width, scene.height);
    storedFloors.reserve(timedSetups.size());
    for (const PrimitiveSetup& s : timedSetups) storedFloors.push_back(ZBufferMemory::storedValue(s.zFloor, cfg));
  }
  HierarchicalZUnit* hizUnit = hiz ? &*hiz : nullptr;

  HostInterfaceUnit host(HostInterfaceUnit::Params::from(cfg), timedSetups, hostToSetup);
  SetupUnit setup(SetupUnit::Params::from(cfg), timedSetups, hostToSetup, setupToTraversal);
  TraversalUnit traversal(TraversalUnit::Params::from(cfg), timedSetups, trace, setupToTraversal, toPipeline, hizUnit,
                          std::move(storedFloors));
  const PixelPipelineUnit::Params pipeParams = PixelPipelineUnit::Params::from(cfg);
  std::vector<PixelPipelineUnit> pipelines;
  pipelines.reserve(P);
  for (std::size_t p = 0; p < P; ++p)
    pipelines.emplace_back("pixel_pipeline_" + std::to_string(p), pipeParams, wires, trace, *toPipeline[p], *toZ[p],
                           st.pixels, &zb);
  ZBufferUnit zunit(ZBufferUnit::Params::from(cfg), cfg, wires, zb, toZ, toShading, st.pixels);
  zunit.reportWritesTo(hizUnit);
  std::vector<ShadingUnit> shading;
  shading.reserve(P);
  for (std::size_t p = 0; p < P; ++p)
    shading.emplace_back("shading_" + std::to_string(p), ShadingUnit::Params::from(cfg), wires, *toShading[p]);

  // The tick order within a cycle: the hierarchical Z unit ticks after traversal (its
  // lookups count as busy). With more than one thread, thread 0 runs the loop while the
  // others fill the trace ahead of it (the traversal unit waits for a primitive not yet
  // filled); the loop's time is its wall time less those waits. The trace's time is from
  // the planning to the last pixel filled, so with threads the two overlap.
  // The item clock, where it applies, computes the same cycles and counts without ticking
  // these units (item_clock.h).
  const bool byItems = clock == MachineClock::Items && itemClockApplies(cfg);
  st.simulator_clock = byItems ? "items" : clock == MachineClock::EveryCycle ? "every cycle" : "repeated ticks";
  ItemClockRun items;
  double loopSeconds = 0, traceDone = 0;
  std::exception_ptr loopError;
  const auto runLoop = [&] {
    const auto loop0 = std::chrono::steady_clock::now();
    try {
      if (byItems) items = runItemClock(cfg, timedSetups, trace, zb, st.pixels);
      else runMachine(clock, wires, st.fast_forwarded, host, setup, traversal, pipelines, zunit, hiz, shading);
    } catch (...) {
      loopError = std::current_exception();
    }
    loopSeconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - loop0).count();
  };
  const auto sinceTrace = [&] { return std::chrono::duration<double>(std::chrono::steady_clock::now() - tr0).count(); };
  if (filled) {
    runLoop();  // nothing to fill
  } else {
#pragma omp parallel num_threads(nt)
    {
      // A team of one (no thread to spare) fills the trace first, then runs the loop.
      if (omp_get_num_threads() == 1) {
        trace.fillAhead();
        traceDone = sinceTrace();
        runLoop();
      } else if (omp_get_thread_num() == 0) {
        runLoop();
      } else {
        trace.fillAhead();
#pragma omp critical(qacc_trace_done)
        traceDone = std::max(traceDone, sinceTrace());
      }
    }
  }
  if (loopError) std::rethrow_exception(loopError);
  if (!filled) trace.finishFill();
  st.overflow.add(trace.overflow);
  st.trace_seconds = traceDone;
  st.loop_seconds = loopSeconds - (filled ? 0.0 : trace.waitSeconds());
  std::uint64_t delivered = 0, culled = 0;
  if (byItems) {
    st.cycles = items.cycles;
    st.units.insert(st.units.end(), items.units.begin(), items.units.end());
    delivered = items.delivered;
    culled = items.culled;
    st.hiz = items.hiz;
  } else {
    st.cycles = wires.now();
    appendUnitStats(st.units, host, setup, traversal, pipelines, zunit, hiz, shading);
    if (hizUnit) {
      st.hiz = hizUnit->counters;
      st.hiz.enabled = true;
    }
    for (const ShadingUnit& u : shading) delivered += u.delivered();
    culled = setup.culled();
  }
  if (delivered != st.pixels.written)
    throw std::logic_error("hw-cycle: shading delivered " + std::to_string(delivered) + " of " +
                           std::to_string(st.pixels.written) + " pixels");
  if (culled != st.culled_at_host)
    throw std::logic_error("hw-cycle: setup culled " + std::to_string(culled) + " of " +
                           std::to_string(st.culled_at_host) + " primitives");
  if (keep) *keep = std::move(planned);
}

}  // namespace

HwRender renderHwCycle(const Scene& scene, const HwConfig& cfg, int threads, MachineClock clock,
                       DatapathReuse* reuse) {
  const auto t0 = std::chrono::steady_clock::now();
  const int nt = threads > 0 ? threads : omp_get_max_threads();
  HwRender out;
  HwStats& st = out.stats;
  st.describeRun("hw-cycle", cfg, scene.name, scene.width, scene.height, nt);
  st.priceNeeds(scene);

  // The setup arithmetic is computed up front (in parallel); the setup unit's timing is
  // simulated from each primitive's operation count. A render under the same datapath kept
  // in `reuse` gives the setups, the trace and, for the same winners, the frame.
  DatapathReuse::Entry* kept = reuse ? reuse->find(scene.width, scene.height, cfg) : nullptr;
  const bool keepThis = reuse && !kept && reuse->mayKeep(scene.width, scene.height);
  DatapathReuse::Entry fresh;
  if (!kept) fresh.setup = FrameSetup::build(scene, cfg, nt);
  const FrameSetup& fs = kept ? kept->setup : fresh.setup;
  st.overflow.add(fs.overflow);
  const CsgFrame csg(scene, cfg, scene.width, scene.height);
  ZBufferMemory zb(scene.width, scene.height);
  runTimedPass(scene, cfg, fs, csg, zb, nt, clock, st, kept ? &kept->trace : nullptr, keepThis ? &fresh.trace : nullptr);
  runCsgCyclePass(csg, fs, cfg, scene.width, scene.height, zb, nt, clock, st);
  if (kept && kept->winners.sameRecords(zb)) {
    out.fb = kept->frame;
    st.distinct_written = kept->distinct;
    st.reused = "setup, pixel trace, frame";
  } else {
    out.fb = resolveFrame(scene, cfg, fs, zb, nt, st);
    if (kept) st.reused = "setup, pixel trace";
  }
  if (keepThis) {
    fresh.winners = std::move(zb);
    fresh.frame = out.fb;
    fresh.distinct = st.distinct_written;
    reuse->keep(scene.width, scene.height, cfg, std::move(fresh));
  }
  st.host_seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
  return out;
}

}  // namespace qacc
