// Image checks shared by the render tests of surfaces made of pieces: holes along shared
// faces show background inside the outline, or the inside of a closed surface.
#pragma once
#include <cstddef>
#include <functional>
#include <queue>
#include <vector>

#include <Eigen/Dense>

#include "modeling/scene/scene.h"
#include "raster/image/frame_buffer.h"

namespace qacc {

// Background pixels not connected to the image border (holes inside the projected surface).
inline int enclosedBackgroundPixels(const FrameBuffer& fb) {
  std::vector<char> seen(fb.pixels(), 0);
  std::queue<int> q;
  auto push = [&](int x, int y) {
    if (x < 0 || y < 0 || x >= fb.width || y >= fb.height) return;
    const int i = y * fb.width + x;
    if (seen[std::size_t(i)] || fb.object[std::size_t(i)] >= 0) return;
    seen[std::size_t(i)] = 1;
    q.push(i);
  };
  for (int x = 0; x < fb.width; ++x) push(x, 0), push(x, fb.height - 1);
  for (int y = 0; y < fb.height; ++y) push(0, y), push(fb.width - 1, y);
  while (!q.empty()) {
    const int i = q.front();
    q.pop();
    const int x = i % fb.width, y = i / fb.width;
    push(x + 1, y), push(x - 1, y), push(x, y + 1), push(x, y - 1);
  }
  int holes = 0;
  for (std::size_t i = 0; i < fb.pixels(); ++i)
    if (fb.object[i] < 0 && !seen[i]) ++holes;
  return holes;
}

// Background pixels whose 8 neighbours are all covered.
inline int pinholes(const FrameBuffer& fb) {
  int n = 0;
  for (int y = 1; y + 1 < fb.height; ++y)
    for (int x = 1; x + 1 < fb.width; ++x) {
      if (fb.object[std::size_t(y) * fb.width + x] >= 0) continue;
      bool closed = true;
      for (int dy = -1; dy <= 1; ++dy)
        for (int dx = -1; dx <= 1; ++dx)
          closed = closed && fb.object[std::size_t(y + dy) * fb.width + (x + dx)] >= 0;
      if (closed) ++n;
    }
  return n;
}

// Background pixels of `test` where `truth` covers the whole (2m+1)^2 neighbourhood.
inline int missedInside(const FrameBuffer& truth, const FrameBuffer& test, int m) {
  int n = 0;
  for (int y = m; y + m < truth.height; ++y)
    for (int x = m; x + m < truth.width; ++x) {
      if (test.object[std::size_t(y) * test.width + x] >= 0) continue;
      bool inside = true;
      for (int dy = -m; dy <= m; ++dy)
        for (int dx = -m; dx <= m; ++dx)
          inside = inside && truth.object[std::size_t(y + dy) * truth.width + (x + dx)] >= 0;
      if (inside) ++n;
    }
  return n;
}

// Pixels whose visible point is on the inside of a closed surface (f <= 0 inside: the
// outward gradient faces away from the viewer): through a crack or pinhole one sees the back
// of the surface from inside. Grazing points (|cos| < 0.05) are not counted, nor the points
// `expected` accepts (seen through an opening the surface has on purpose).
inline int insideViews(const Scene& s, const FrameBuffer& fb,
                       const std::function<bool(const Eigen::Vector3d&)>& expected = {}) {
  const Eigen::Matrix4d Minv = s.camera.worldToWindow(fb.width, fb.height).inverse();
  int n = 0;
  for (int y = 0; y < fb.height; ++y)
    for (int x = 0; x < fb.width; ++x) {
      const std::size_t i = std::size_t(y) * std::size_t(fb.width) + std::size_t(x);
      if (fb.primitive[i] < 0) continue;
      const Eigen::Vector4d X = Minv * Eigen::Vector4d(x + 0.5, y + 0.5, fb.depth[i], 1.0);
      const Eigen::Vector3d p = X.head<3>() / X.w();
      const Eigen::Vector3d g = s.primitives[std::size_t(fb.primitive[i])].quadric.gradient(p);
      const Eigen::Vector3d v = s.camera.toViewer(p);
      if (g.dot(v) < -0.05 * g.norm() * v.norm() && !(expected && expected(p))) ++n;
    }
  return n;
}

}  // namespace qacc
