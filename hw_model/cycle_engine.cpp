#include "hw_model/cycle_engine.h"

#include <omp.h>

#include <chrono>
#include <memory>
#include <stdexcept>

#include "hw_model/depth_unit.h"
#include "hw_model/host_interface.h"
#include "hw_model/hw_scene_setup.h"
#include "hw_model/pixel_pipeline_unit.h"
#include "hw_model/setup_unit.h"
#include "hw_model/shading_unit.h"
#include "hw_model/traversal_unit.h"
#include "hw_model/zbuffer_unit.h"
#include "raster/shading.h"

namespace qacc {

namespace {

struct ColourWriter {
  const Scene* scene;
  const HwConfig* cfg;
  const HwSceneSetup* hs;
  FrameBuffer* fb;
  std::vector<std::int32_t>* order;  // last primitive written per pixel
  OverflowCounter ovf;
  static void write(void* ctx, const ShadeRequest& r) {
    auto* w = static_cast<ColourWriter*>(ctx);
    const PrimitiveSetup& s = w->hs->setups[std::size_t(r.prim)];
    const auto rgb = ShadingUnit::shade(s, w->hs->lighting, *w->cfg, r.x - s.x0, r.y - s.y0, r.z, r.cap, w->ovf);
    const std::size_t pix = std::size_t(r.y) * std::size_t(w->fb->width) + std::size_t(r.x);
    for (int c = 0; c < 3; ++c) w->fb->color.data[pix * 3 + c] = rgb[std::size_t(c)];
    w->fb->object[pix] = s.object;
    w->fb->primitive[pix] = r.prim;
    const double lsb = std::ldexp(1.0, -w->cfg->zbuffer_bits);
    w->fb->depth[pix] = (double(DepthUnit::zbufferValue(r.z, *w->cfg)) + 0.5) * lsb;
  }
};

}  // namespace

HwRender renderHwCycle(const Scene& scene, const HwConfig& cfg, int threads) {
  const auto t0 = std::chrono::steady_clock::now();
  const int nt = threads > 0 ? threads : omp_get_max_threads();
  HwRender out;
  HwStats& st = out.stats;
  st.engine = "hw-cycle";
  st.config = cfg.name;
  st.scene = scene.name;
  st.width = scene.width;
  st.height = scene.height;
  st.threads = nt;
  st.clock_mhz = cfg.clock_mhz;

  // The setup arithmetic is computed up front (in parallel); the setup unit's timing is
  // simulated below from each primitive's operation count.
  const HwSceneSetup hs = HwSceneSetup::build(scene, cfg, nt);
  st.overflow.add(hs.overflow);
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
  out.fb = FrameBuffer(scene.width, scene.height, toSrgb8(scene.background));
  ColourWriter writer{&scene, &cfg, &hs, &out.fb, nullptr, {}};

  std::vector<std::unique_ptr<Unit>> units;
  units.push_back(std::make_unique<HostInterface>(hs.setups, cfg, hostFifo));
  units.push_back(std::make_unique<SetupUnit>(hs.setups, cfg, hostFifo, setupFifo));
  units.push_back(std::make_unique<TraversalUnit>(hs.setups, cfg, setupFifo, pixFifo));
  for (std::size_t p = 0; p < P; ++p)
    units.push_back(std::make_unique<PixelPipelineUnit>("pixel_pipeline_" + std::to_string(p), hs.setups, cfg,
                                                        pixFifo[p], zFifo[p], st.pixels, st.overflow));
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

  std::uint64_t now = 0, quiet = 0;
  for (;;) {
    bool changed = false;
    for (auto& u : units) changed |= u->tick(now);
    changed |= commitAll();
    ++now;
    bool working = !fifosIdle();
    for (auto& u : units) working |= u->holdsWork();
    if (!working) break;
    if (changed) {
      quiet = 0;
      continue;
    }
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
  for (auto& u : units) st.units.push_back(u->stats());
  std::uint64_t distinct = 0;
  for (std::size_t i = 0; i < out.fb.pixels(); ++i) distinct += out.fb.object[i] >= 0;
  st.distinct_written = distinct;
  st.overflow.shading.events += writer.ovf.events;
  st.host_seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
  return out;
}

}  // namespace qacc
