// Silhouette distance (design §4): distance between the object-boundary pixels of the
// reference and of the test image. A boundary pixel is a pixel covered by an object one of
// whose 4 neighbours inside the image shows something else (another object or background):
// the inner rim of every silhouette, and both sides of an edge between two objects.
// Distances come from an exact Euclidean distance transform (distance_transform.h).
//  - hausdorff: max over both boundary sets of the distance to the other set;
//  - mean (symmetric mean chamfer): the average of those distances over both sets.
#pragma once
#include <cstddef>
#include <cstdint>
#include <vector>

#include "raster/image/frame_buffer.h"
#include "raster/image/image.h"

namespace qacc {

struct SilhouetteDistance {
  std::size_t reference_boundary = 0;  // boundary pixels of the reference
  std::size_t test_boundary = 0;
  double hausdorff = 0;   // pixels; +inf when exactly one of the images has a boundary
  double mean = 0;        // pixels (symmetric mean chamfer distance)
  // Fraction of reference boundary pixels with a test boundary pixel within `tolerance`.
  double within_tolerance = 1.0;
  double tolerance = 1.0;
};

// Boundary mask (1 = boundary) of an object-id buffer.
std::vector<std::uint8_t> boundaryMask(const UninitVector<std::int32_t>& ids, int width, int height);
SilhouetteDistance silhouetteDistance(const FrameBuffer& reference, const FrameBuffer& test,
                                      double tolerance = 1.0);
// Per-pixel distance map for heat maps: at each boundary pixel of either image, its distance
// to the other image's boundary (0 elsewhere).
ImageF silhouetteDistanceMap(const FrameBuffer& reference, const FrameBuffer& test);

}  // namespace qacc
