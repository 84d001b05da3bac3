// Frame resolve: the Z-buffer's winners shaded (shading_arithmetic.h) into the frame
// buffer — colour, window depth from the stored Z value, object and primitive. `hw` does
// it per tile as soon as the tile's last primitive is drawn; `hw-cycle` for the whole
// frame once the pipeline has drained (colours are a pure function of the final winners).
#pragma once
#include <array>
#include <cstdint>

#include "hw_model/config/hw_config.h"
#include "hw_model/datapath/zbuffer_memory.h"
#include "hw_model/engines/frame_setup.h"
#include "hw_model/report/hw_stats.h"
#include "modeling/scene/scene.h"
#include "raster/image/frame_buffer.h"

namespace qacc {

// Writes pixels [x0, x1) of row y (row[i] is pixel x0 + i's record) into the frame buffer:
// each run of one primitive's winners shaded as a span (shadeSpan), the pixels without a
// winner cleared to the background (so that every pixel is written once, with no clear
// before); returns the pixels with a winner.
std::uint64_t resolveRow(const HwConfig& cfg, const FrameSetup& fs, int x0, int x1, int y, const ZEntry* row,
                         const FrameBuffer::Background& background, FrameBuffer& fb, OverflowCounter& ovf);

// Shades every winner of a frame-sized Z-buffer; counts the distinct pixels written.
FrameBuffer resolveFrame(const Scene& scene, const HwConfig& cfg, const FrameSetup& fs, const ZBufferMemory& zb,
                         int threads, HwStats& stats);

}  // namespace qacc
