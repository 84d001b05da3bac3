// HwSceneSetup: the per-frame state both accelerator engines start from — the setup
// unit's output for every primitive (PrimitiveSetup, computed once, in parallel, in scene
// order) and the quantised lighting — plus the final shading pass that turns the
// Z-buffer's winners into the frame buffer.
#pragma once
#include <cstdint>
#include <vector>

#include "hw_model/config/hw_config.h"
#include "hw_model/report/hw_stats.h"
#include "hw_model/datapath/primitive_setup.h"
#include "hw_model/timing/shading_unit.h"
#include "modeling/scene/scene.h"
#include "raster/image/frame_buffer.h"

namespace qacc {

struct HwSceneSetup {
  std::vector<PrimitiveSetup> setups;
  LightingSetup lighting;
  OverflowCounters overflow;  // setup overflows
  static HwSceneSetup build(const Scene& scene, const HwConfig& cfg, int threads);
};

// What the Z-buffer holds per pixel: the stored Z value and, for the final shading, the
// winner's identity and internal depth. One record per pixel, so a Z test touches one
// cache line.
struct ZEntry {
  std::int64_t depth = 0;                // the winner's depth in the internal format
  std::uint32_t z = 0xFFFFFFFFu;         // stored Z value (UINT32_MAX = cleared)
  std::int32_t prim = -1;                // winning primitive (-1 = none)
  std::int16_t cap = -1;                 // its cap plane (-1 = surface)
};

struct ZBufferState {
  int width = 0, height = 0;
  std::vector<ZEntry> px;
  ZBufferState(int w, int h);
  std::size_t size() const { return px.size(); }
  void clear();  // back to the cleared state (no winner anywhere)
};

// Shades one Z-buffer winner (ShadingUnit::shade) into pixel (x, y) of the frame buffer:
// colour, window depth from the stored Z value, object and primitive.
void resolvePixel(const HwConfig& cfg, const HwSceneSetup& hs, int x, int y, const ZEntry& e, FrameBuffer& fb,
                  OverflowCounter& ovf);

// Shades the winners (ShadingUnit::shade) into a frame buffer; counts distinct pixels.
FrameBuffer resolveFrame(const Scene& scene, const HwConfig& cfg, const HwSceneSetup& hs, const ZBufferState& zb,
                         int threads, HwStats& stats);

}  // namespace qacc
