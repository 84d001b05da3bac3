// Functional accelerator engine (`--engine hw`): the bit-accurate datapaths without
// timing, as fast as possible. Setup for all primitives in parallel; then screen tiles in
// parallel (OpenMP), each drawing the primitives that overlap it in scene order, each
// span through the PixelDatapath's forward differences; Z test in primitive order
// (equal depths keep the earlier primitive) in a tile-local Z-buffer; the tile's winners
// are shaded as soon as its last primitive is drawn. Every pixel
// depends only on the scene and the configuration: identical output for any thread count.
#pragma once
#include "hw_model/config/hw_config.h"
#include "hw_model/report/hw_stats.h"
#include "modeling/scene/scene.h"
#include "raster/image/frame_buffer.h"

namespace qacc {

struct HwRender {
  FrameBuffer fb;
  HwStats stats;
};

HwRender renderHw(const Scene& scene, const HwConfig& cfg, int threads = 0);

}  // namespace qacc
