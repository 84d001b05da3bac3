// The scene of `qacc bench-load`: n spheres of radius 0.01 on a square grid over [-1, 1]²
// in the plane z = 0, all in view of a perspective camera at (0, 0, 5) (field of view 30
// degrees, 320x240), one object per line. The grid's side is ceil(√n), so every sphere is
// on screen and view culling keeps them all: the load measures the full per-object work.
#pragma once
#include <cstddef>
#include <string>

namespace qacc {

std::string sphereGridScene(std::size_t n);

}  // namespace qacc
