// Reference renderer (design §3.1): exact per-pixel ray casting in double precision, the
// ground truth of every metric. Per primitive: window-space quadric and half-spaces, an
// exact screen bounding box (contour conic ∩ projected clip polytope); per pixel: stable
// roots, clip half-spaces, solid caps as depth-interval logic (pixel_hit.h), Z-buffer in
// primitive order (equal depths keep the earlier primitive). Objects with an exact surface
// are ray-cast from it instead of from their quadric pieces. Work is split into screen
// tiles rendered in parallel (OpenMP); every pixel depends only on the scene, so the
// output is byte-identical for any thread count.
#pragma once
#include "modeling/scene/scene.h"
#include "raster/image/frame_buffer.h"

namespace qacc {

// Changes whenever the reference's output for a scene can change: part of the key of the
// reference render cache (tools/engines/reference_cache.h).
constexpr const char* kReferenceRendererVersion = "qacc-reference/4";  // 2: screen boxes by piece_extent.h; 3: clip planes scaled by powers of two (unit_plane.h); 4: scenes held relative to an origin near their view (scene_origin.h)

struct ReferenceStats {
  double setup_ms = 0;      // window-space setup and binning
  double visibility_ms = 0; // per-pixel root finding, depth test and shading of the winners, tile by tile
  long long pixel_tests = 0;  // (pixel, primitive) pairs evaluated
};

// threads <= 0: OpenMP's default.
FrameBuffer renderReference(const Scene& scene, int threads = 0, ReferenceStats* stats = nullptr);

}  // namespace qacc
