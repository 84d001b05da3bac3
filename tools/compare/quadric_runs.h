// The quadrics of the scene: the exact reference (the truth every image is measured
// against) and the accelerator — `hw` for the image and host time, `hw-cycle` for the
// modeled cycles (the two are bit-identical by design, and checked).
#pragma once
#include "raster/image/frame_buffer.h"
#include "tools/compare/compare_plan.h"
#include "tools/compare/compare_row.h"

namespace qacc::compare {

struct QuadricRuns {
  FrameBuffer ref;
  double ref_ms = 0;
  Row hw;                  // engine "hw", measured against ref
  bool identical = false;  // hw-cycle's image is hw's
};

QuadricRuns renderQuadrics(const ComparePlan& plan, int threads);

}  // namespace qacc::compare
