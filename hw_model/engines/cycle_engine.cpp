#include "hw_model/engines/cycle_engine.h"

#include <omp.h>

#include <chrono>
#include <memory>
#include <stdexcept>

#include "hw_model/timing/host_interface_unit.h"
#include "hw_model/engines/frame_setup.h"
#include "hw_model/timing/pixel_pipeline_unit.h"
#include "hw_model/engines/pixel_trace.h"
#include "hw_model/timing/setup_unit.h"
#include "hw_model/timing/shading_unit.h"
#include "hw_model/timing/traversal_unit.h"
#include "hw_model/timing/zbuffer_unit.h"

namespace qacc {

namespace {

// The shading units' output port. Colours are a pure function of the Z-buffer's final
// winners (ShadingUnit::shade of the same inputs), so the frame is resolved once the
// pipeline has drained (resolveFrame: resolvePixel, as `hw` does per tile); the port counts what the
// shading units delivered, which the functional engine cannot know.
struct ColourWriter {
  std::uint64_t delivered = 0;
  static void write(void* ctx, const ShadeRequest& r) {
    (void)r;
    ++static_cast<ColourWriter*>(ctx)->delivered;
  }
};

}  // namespace

HwRender renderHwCycle(const Scene& scene, const HwConfig& cfg, int threads) {
  const auto t0 = std::chrono::steady_clock::now();
  const int nt = threads > 0 ? threads : omp_get_max_threads();
  HwRender out;
  HwStats& st = out.stats;
  st.describeRun("hw-cycle", cfg, scene.name, scene.width, scene.height, nt);

  // The setup arithmetic is computed up front (in parallel); the setup unit's timing is
  // simulated below from each primitive's operation count.
  const HwSceneSetup hs = HwSceneSetup::build(scene, cfg, nt);
  st.overflow.add(hs.overflow);
  // So is the pixel arithmetic (functional-first, timing-directed: pixel_trace.h).
  const auto tr0 = std::chrono::steady_clock::now();
  const PixelTrace trace = PixelTrace::build(hs.setups, cfg, nt);
  st.trace_seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - tr0).count();
  st.overflow.add(trace.overflow);
  st.primitives = hs.setups.size();
  for (const PrimitiveSetup& s : hs.setups) {
    st.visible_primitives += s.visible;
    st.facet_primitives += s.visible && s.facet;
  }

  const std::size_t P = std::size_t(cfg.pipelines);
  Fifo<int> hostFifo(std::size_t(cfg.host_fifo_depth)), setupFifo(std::size_t(cfg.setup_fifo_depth));
  std::vector<Fifo<PixelToken>> pixFifo(P, Fifo<PixelToken>(std::size_t(cfg.pixel_fifo_depth)));
  std::vector<Fifo<ZRequest>> zFifo(P, Fifo<ZRequest>(std::size_t(cfg.pixel_fifo_depth)));
  std::vector<Fifo<ShadeRequest>> shadeFifo(P, Fifo<ShadeRequest>(std::size_t(cfg.pixel_fifo_depth)));

  ZBufferState zb(scene.width, scene.height);
  ColourWriter writer;

  std::vector<std::unique_ptr<Unit>> units;
  units.push_back(std::make_unique<HostInterface>(hs.setups, cfg, hostFifo));
  units.push_back(std::make_unique<SetupUnit>(hs.setups, cfg, hostFifo, setupFifo));
  units.push_back(std::make_unique<TraversalUnit>(hs.setups, trace, setupFifo, pixFifo));
  for (std::size_t p = 0; p < P; ++p)
    units.push_back(std::make_unique<PixelPipelineUnit>("pixel_pipeline_" + std::to_string(p), trace, cfg,
                                                        pixFifo[p], zFifo[p], st.pixels, &zb));
  units.push_back(std::make_unique<ZBufferUnit>(cfg, zb, zFifo, shadeFifo, st.pixels));
  for (std::size_t p = 0; p < P; ++p)
    units.push_back(std::make_unique<ShadingUnit>("shading_" + std::to_string(p), cfg, shadeFifo[p],
                                                  &ColourWriter::write, &writer));

  auto commitAll = [&]() {
    bool c = hostFifo.commit();
    c |= setupFifo.commit();
    for (std::size_t p = 0; p < P; ++p) {
      c |= pixFifo[p].commit();
      c |= zFifo[p].commit();
      c |= shadeFifo[p].commit();
    }
    return c;
  };
  auto fifosIdle = [&]() {
    if (!hostFifo.idle() || !setupFifo.idle()) return false;
    for (std::size_t p = 0; p < P; ++p)
      if (!pixFifo[p].idle() || !zFifo[p].idle() || !shadeFifo[p].idle()) return false;
    return true;
  };

  const auto loop0 = std::chrono::steady_clock::now();
  // The frame ends with the first cycle after which no unit holds work and every FIFO is
  // empty. That state can only be entered by a cycle where something changed, and the
  // cycle after it changes nothing, so the check runs only on unchanged cycles: ending
  // there, the frame took one cycle less than the loop ran.
  std::uint64_t now = 0, quiet = 0;
  bool prevChanged = false;
  for (;;) {
    bool changed = false;
    for (auto& u : units) changed |= u->tick(now);
    changed |= commitAll();
    ++now;
    if (changed) {
      quiet = 0;
      prevChanged = true;
      continue;
    }
    bool working = !fifosIdle();
    for (auto& u : units) working |= u->holdsWork();
    if (!working) {
      if (prevChanged) {  // the idle cycle the loop ran past the end is not part of the frame
        --now;
        for (auto& u : units) u->retractIdle();
      }
      break;
    }
    prevChanged = false;
    // Nothing moved: jump to the next timed event.
    std::uint64_t next = std::numeric_limits<std::uint64_t>::max();
    for (auto& u : units) next = std::min(next, u->nextEvent());
    if (next == std::numeric_limits<std::uint64_t>::max() || ++quiet > 1000000)
      throw std::runtime_error("hw-cycle: the pipeline deadlocked at cycle " + std::to_string(now));
    if (next > now) {
      const std::uint64_t skip = next - now;
      for (auto& u : units) u->skip(skip);
      st.fast_forwarded += skip;
      now = next;
    }
  }
  st.cycles = now;
  st.loop_seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - loop0).count();
  for (auto& u : units) st.units.push_back(u->stats());
  if (writer.delivered != st.pixels.written)
    throw std::logic_error("hw-cycle: shading delivered " + std::to_string(writer.delivered) + " of " +
                           std::to_string(st.pixels.written) + " pixels");
  out.fb = resolveFrame(scene, cfg, hs, zb, nt, st);
  st.host_seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
  return out;
}

}  // namespace qacc
