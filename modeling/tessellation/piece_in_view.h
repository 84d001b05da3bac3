// Whether a tessellated piece surely reaches the view: a point of the piece itself (on its
// surface, inside its clip region up to rounding) lies within kInViewMarginPixels of the
// image, between the near and far planes. Such a piece meets the view volume of view culling
// (scene/view_volume.h: the image widened by ViewVolume::kMarginPixels = 2), so every
// conservative culling test keeps it (loader/view_culling.h): it is present in the scene
// whether or not the scene was culled for this view. The facets' shared boundaries are
// stitched only between such pieces (shared_boundaries.h, tessellateScene), so a kept
// piece's triangles never depend on the neighbours culling removed.
//
// The points tried: the piece's surface vertices that lie on its quadric (up to rounding: a
// tessellation can leave surface vertices far from the surface, and such a vertex on screen
// proves nothing — on bspline_g1 it made pieces whose exact bounds miss the view count as in
// it, so culling them changed a kept neighbour's stitched facets), then, for each surface
// triangle that crosses the image, the centroid of its part inside the image moved onto the surface
// (Newton projection along the gradient) — so that a piece larger than a zoomed-in view, with
// no vertex on screen, is still found. A piece whose facets cross the image but whose surface
// does not come within the margin is not stitched (nor would culling keep it).
#pragma once
#include <cstddef>
#include <vector>

#include "modeling/geometry/half_space.h"
#include "modeling/geometry/primitive.h"
#include "modeling/scene/screen_view.h"
#include "modeling/tessellation/tessellation.h"

namespace qacc::tess {

// Below ViewVolume::kMarginPixels: a point within it is inside the culling volume with a
// pixel to spare for the rounding of the point.
constexpr double kInViewMarginPixels = 1.0;

class PieceInView {
 public:
  explicit PieceInView(const ScreenView& view);
  // `surfaceTriangles`: the first triangles of `mesh`, the piece's surface (the rest are caps).
  bool surelyInView(const Primitive& prim, const TriangleMesh3& mesh, std::size_t surfaceTriangles) const;

 private:
  const ScreenView& view_;
  std::vector<HalfSpace> image_;  // the image's frustum (no margin), world space
};

}  // namespace qacc::tess
