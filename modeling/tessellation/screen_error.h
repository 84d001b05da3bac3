// The projected chord error of a mesh (tessellation.h, `pixel_error`): the window-space
// distance between each chord-error sample of a triangle and its closest point on the
// surface, in the scene's view (scene/screen_view.h).
#pragma once
#include <cstddef>

#include <Eigen/Dense>

#include "modeling/geometry/quadric.h"
#include "modeling/scene/screen_view.h"

namespace qacc {

struct TriangleMesh3;

// Projected chord error of triangles [first, first + count) of `mesh` against `quadric`:
// per sample (the barycentric grid of measureChordError), the window distance in pixels
// between the sample and its closest point on the surface; only samples on screen count.
struct PixelError {
  double max = 0, mean = 0;
  std::size_t samples = 0;
};
PixelError measurePixelError(const TriangleMesh3& mesh, const Quadric& quadric, const ScreenView& view,
                             std::size_t first = 0, std::size_t count = std::size_t(-1), int subdivisions = 6);

}  // namespace qacc
