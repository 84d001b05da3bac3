#include "hw_model/engines/cycle_engine.h"

#include <omp.h>

#include <algorithm>
#include <chrono>
#include <limits>
#include <memory>
#include <stdexcept>
#include <string>

#include "hw_model/engines/csg_tile.h"
#include "hw_model/engines/frame_resolve.h"
#include "hw_model/engines/frame_setup.h"
#include "hw_model/engines/pixel_trace.h"
#include "hw_model/timing/channel_registry.h"
#include "hw_model/timing/host_interface_unit.h"
#include "hw_model/timing/pixel_pipeline_unit.h"
#include "hw_model/timing/setup_unit.h"
#include "hw_model/timing/shading_unit.h"
#include "hw_model/timing/traversal_unit.h"
#include "hw_model/timing/zbuffer_unit.h"

namespace qacc {

HwRender renderHwCycle(const Scene& scene, const HwConfig& cfg, int threads) {
  const auto t0 = std::chrono::steady_clock::now();
  const int nt = threads > 0 ? threads : omp_get_max_threads();
  HwRender out;
  HwStats& st = out.stats;
  st.describeRun("hw-cycle", cfg, scene.name, scene.width, scene.height, nt);
  st.priceNeeds(scene);

  // The setup arithmetic is computed up front (in parallel); the setup unit's timing is
  // simulated below from each primitive's operation count.
  const FrameSetup fs = FrameSetup::build(scene, cfg, nt);
  st.overflow.add(fs.overflow);
  // The leaves of csg objects do not enter the timed machine: they are drawn after it
  // (csg_tile.h), untimed, with the scene-order tie rule, so the image equals hw's.
  const CsgFrame csg(scene, scene.width, scene.height);
  FrameSetup timedCopy;
  if (!csg.trees.empty()) {
    timedCopy.setups = fs.setups;
    for (PrimitiveSetup& s : timedCopy.setups)
      if (csg.treeOfPrimitive[std::size_t(s.index)] >= 0) s.visible = false;
  }
  const std::vector<PrimitiveSetup>& timedSetups = csg.trees.empty() ? fs.setups : timedCopy.setups;
  // So is the pixel arithmetic (functional-first, timing-directed: pixel_trace.h).
  const auto tr0 = std::chrono::steady_clock::now();
  const PixelTrace trace = PixelTrace::build(timedSetups, cfg, nt);
  st.trace_seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - tr0).count();
  st.overflow.add(trace.overflow);
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
  ZBufferMemory zb(scene.width, scene.height);

  std::vector<std::unique_ptr<Unit>> units;
  units.push_back(std::make_unique<HostInterfaceUnit>(HostInterfaceUnit::Params::from(cfg), timedSetups, hostToSetup));
  auto setupUnit = std::make_unique<SetupUnit>(SetupUnit::Params::from(cfg), timedSetups, hostToSetup, setupToTraversal);
  const SetupUnit& setup = *setupUnit;
  units.push_back(std::move(setupUnit));
  units.push_back(std::make_unique<TraversalUnit>(TraversalUnit::Params::from(cfg), timedSetups, trace, setupToTraversal,
                                                  toPipeline));
  const PixelPipelineUnit::Params pipeParams = PixelPipelineUnit::Params::from(cfg);
  for (std::size_t p = 0; p < P; ++p)
    units.push_back(std::make_unique<PixelPipelineUnit>("pixel_pipeline_" + std::to_string(p), pipeParams, wires,
                                                        trace, *toPipeline[p], *toZ[p], st.pixels, &zb));
  units.push_back(
      std::make_unique<ZBufferUnit>(ZBufferUnit::Params::from(cfg), cfg, wires, zb, toZ, toShading, st.pixels));
  std::vector<const ShadingUnit*> shading;
  for (std::size_t p = 0; p < P; ++p) {
    auto u = std::make_unique<ShadingUnit>("shading_" + std::to_string(p), ShadingUnit::Params::from(cfg), wires,
                                           *toShading[p]);
    shading.push_back(u.get());
    units.push_back(std::move(u));
  }

  const auto loop0 = std::chrono::steady_clock::now();
  // The frame ends with the first cycle after which no unit holds work and every FIFO is
  // empty. That state can only be entered by a cycle where something changed, and the
  // cycle after it changes nothing, so the check runs only on unchanged cycles: ending
  // there, the frame took one cycle less than the loop ran.
  std::uint64_t quiet = 0;
  bool prevChanged = false;
  for (;;) {
    bool changed = false;
    const std::uint64_t now = wires.now();
    for (auto& u : units) changed |= u->tick(now);
    changed |= wires.endCycle();
    if (changed) {
      quiet = 0;
      prevChanged = true;
      continue;
    }
    bool working = !wires.idle();
    for (auto& u : units) working |= u->holdsWork();
    if (!working) {
      if (prevChanged) {  // the idle cycle the loop ran past the end is not part of the frame
        wires.retractCycle();
        for (auto& u : units) u->retractIdle();
      }
      break;
    }
    prevChanged = false;
    // Nothing moved: jump to the next timed event.
    std::uint64_t next = std::numeric_limits<std::uint64_t>::max();
    for (auto& u : units) next = std::min(next, u->nextEvent());
    if (next == std::numeric_limits<std::uint64_t>::max() || ++quiet > 1000000)
      throw std::runtime_error("hw-cycle: the pipeline deadlocked at cycle " + std::to_string(wires.now()));
    if (next > wires.now()) {
      const std::uint64_t skip = next - wires.now();
      for (auto& u : units) u->skip(skip);
      st.fast_forwarded += skip;
      wires.skipTo(next);
    }
  }
  st.cycles = wires.now();
  st.loop_seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - loop0).count();
  for (auto& u : units) st.units.push_back(u->stats());
  std::uint64_t delivered = 0;
  for (const ShadingUnit* u : shading) delivered += u->delivered();
  if (delivered != st.pixels.written)
    throw std::logic_error("hw-cycle: shading delivered " + std::to_string(delivered) + " of " +
                           std::to_string(st.pixels.written) + " pixels");
  if (setup.culled() != st.culled_at_host)
    throw std::logic_error("hw-cycle: setup culled " + std::to_string(setup.culled()) + " of " +
                           std::to_string(st.culled_at_host) + " primitives");
  drawCsgFrame(csg, fs, cfg, scene.width, scene.height, zb, nt, st);
  st.csg.estimated_cycles = (st.csg.leaf_pixels + P - 1) / P + (st.csg.interval_ends + P - 1) / P;
  st.cycles += st.csg.estimated_cycles;
  out.fb = resolveFrame(scene, cfg, fs, zb, nt, st);
  st.host_seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
  return out;
}

}  // namespace qacc
