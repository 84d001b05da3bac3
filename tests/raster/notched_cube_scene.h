// The coincident-faces scene of the CSG tests (tests/raster/test_csg_reference.cpp,
// tests/hw_model/test_csg_coincident_faces.cpp): a cube as the intersection of three slab
// quadrics minus a box (a solid half-space clipped by 5 planes) sharing the cube's faces
// x = 1, y = 1 and z = 1 on its corner octant, turned by `angles` (degrees) and seen in
// perspective, 240x240; and the speckles of an image (pixels whose four neighbours agree on
// another primitive).
#pragma once
#include <string>

#include "raster/image/frame_buffer.h"

namespace qacc {

inline std::string notchedCubeScene(const std::string& angles) {
  return R"({"format": "qacc-scene/1", "image": {"width": 240, "height": 240},
      "camera": {"eye": [2.5, 3.1, 3.7], "target": [0, 0, 0], "fov_y_deg": 45, "near": 0.5, "far": 20},
      "objects": [{"type": "csg", "op": "difference", "transform": {"rotate_deg": )" + angles + R"(},
        "children": [
          {"type": "csg", "op": "intersection", "children": [
            {"type": "quadric", "matrix": [[1,0,0,0],[0,0,0,0],[0,0,0,0],[0,0,0,-1]], "solid": true},
            {"type": "quadric", "matrix": [[0,0,0,0],[0,1,0,0],[0,0,0,0],[0,0,0,-1]], "solid": true},
            {"type": "quadric", "matrix": [[0,0,0,0],[0,0,0,0],[0,0,1,0],[0,0,0,-1]], "solid": true}]},
          {"type": "plane", "point": [0, 0, 1], "normal": [0, 0, 1], "solid": true,
           "clip": [[1,0,0,-1],[-1,0,0,0],[0,1,0,-1],[0,-1,0,0],[0,0,-1,0]]}]}]})";
}

inline int countSpeckles(const FrameBuffer& fb) {
  const int W = fb.width, H = fb.height;
  int speckles = 0;
  for (int y = 1; y + 1 < H; ++y)
    for (int x = 1; x + 1 < W; ++x) {
      auto at = [&](int u, int v) { return fb.primitive[std::size_t(v) * std::size_t(W) + std::size_t(u)]; };
      const int n = at(x - 1, y);
      if (at(x + 1, y) == n && at(x, y - 1) == n && at(x, y + 1) == n && at(x, y) != n) ++speckles;
    }
  return speckles;
}

}  // namespace qacc
