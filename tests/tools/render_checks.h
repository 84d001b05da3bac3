// Image checks shared by the render tests of surfaces made of pieces: holes along shared
// faces show background inside the outline, or the inside of a closed surface.
#pragma once
#include <algorithm>
#include <cstddef>
#include <functional>
#include <queue>
#include <vector>

#include <Eigen/Dense>

#include "modeling/scene/scene.h"
#include "modeling/scene/screen_view.h"
#include "raster/image/frame_buffer.h"

namespace qacc {

// Background pixels not connected to the image border (holes inside the projected surface);
// with `truth`, only those the truth covers (a torus's own hole is not counted).
inline int enclosedBackgroundPixels(const FrameBuffer& fb, const FrameBuffer* truth = nullptr) {
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
    if (fb.object[i] < 0 && !seen[i] && (!truth || truth->object[i] >= 0)) ++holes;
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

// The world point a frame buffer shows at pixel (x, y) with window depth `depth` (Minv: the
// inverse of the camera's world -> window matrix for the buffer's size).
inline Eigen::Vector3d pixelPoint(const Eigen::Matrix4d& Minv, int x, int y, double depth) {
  const Eigen::Vector4d X = Minv * Eigen::Vector4d(x + 0.5, y + 0.5, depth, 1.0);
  return X.head<3>() / X.w();
}

// Whether p, on primitive `prim`, is seen from inside its closed surface (f <= 0 inside: the
// outward gradient faces away from the viewer), grazing points (|cos| < 0.05) excepted.
inline bool seenFromInside(const Scene& s, int prim, const Eigen::Vector3d& p) {
  const Eigen::Vector3d g = s.primitives[std::size_t(prim)].quadric.gradient(p);
  const Eigen::Vector3d v = s.camera.toViewer(p);
  return g.dot(v) < -0.05 * g.norm() * v.norm();
}

// Pixels whose visible point is on the inside of a closed surface (seenFromInside): through a
// crack or pinhole one sees the back of the surface from inside. The points `expected`
// accepts (seen through an opening the surface has on purpose) are not counted.
inline int insideViews(const Scene& s, const FrameBuffer& fb,
                       const std::function<bool(const Eigen::Vector3d&)>& expected = {}) {
  const Eigen::Matrix4d Minv = s.camera.worldToWindow(fb.width, fb.height).inverse();
  int n = 0;
  for (int y = 0; y < fb.height; ++y)
    for (int x = 0; x < fb.width; ++x) {
      const std::size_t i = std::size_t(y) * std::size_t(fb.width) + std::size_t(x);
      if (fb.primitive[i] < 0) continue;
      const Eigen::Vector3d p = pixelPoint(Minv, x, y, fb.depth[i]);
      if (seenFromInside(s, fb.primitive[i], p) && !(expected && expected(p))) ++n;
    }
  return n;
}

// Where a tessellation may show the background or back faces without any crack: pixels
// within `margin` px (Chebyshev) of the truth's outline or of one of its occluding contours —
// a covered pixel of the truth (the reference's frame buffer of the same view) next to the
// background or to a pixel more than `jumpPx` pixels' worth of distance farther away. There
// the chords of a surface's far side reach past those of its near side, and a chord leaves
// a pixel centre the true surface covers by a sliver.
inline std::vector<char> nearTruthContours(const Scene& s, const FrameBuffer& truth, int margin, double jumpPx) {
  const Eigen::Matrix4d Minv = s.camera.worldToWindow(truth.width, truth.height).inverse();
  const ScreenView view(s.camera, truth.width, truth.height);
  const Eigen::Vector3d forward = s.camera.forward();
  const int W = truth.width, H = truth.height;
  std::vector<double> dist(truth.pixels(), 0.0), scale(truth.pixels(), 0.0);
  for (int y = 0; y < H; ++y)
    for (int x = 0; x < W; ++x) {
      const std::size_t i = std::size_t(y) * std::size_t(W) + std::size_t(x);
      if (truth.object[i] < 0) continue;
      const Eigen::Vector3d p = pixelPoint(Minv, x, y, truth.depth[i]);
      dist[i] = (p - s.camera.eye).dot(forward);
      scale[i] = view.pixelsPerUnit(p);
    }
  std::vector<char> contour(truth.pixels(), 0);
  for (int y = 0; y < H; ++y)
    for (int x = 0; x < W; ++x) {
      const std::size_t i = std::size_t(y) * std::size_t(W) + std::size_t(x);
      if (truth.object[i] < 0) continue;
      const int nx[4] = {x + 1, x - 1, x, x}, ny[4] = {y, y, y + 1, y - 1};
      for (int k = 0; k < 4 && !contour[i]; ++k) {
        if (nx[k] < 0 || ny[k] < 0 || nx[k] >= W || ny[k] >= H) continue;
        const std::size_t j = std::size_t(ny[k]) * std::size_t(W) + std::size_t(nx[k]);
        contour[i] = truth.object[j] < 0 || (dist[j] - dist[i]) * scale[i] > jumpPx;
      }
    }
  std::vector<char> near(truth.pixels(), 0);
  for (int y = 0; y < H; ++y)
    for (int x = 0; x < W; ++x) {
      if (!contour[std::size_t(y) * std::size_t(W) + std::size_t(x)]) continue;
      for (int yy = std::max(0, y - margin); yy <= std::min(H - 1, y + margin); ++yy)
        for (int xx = std::max(0, x - margin); xx <= std::min(W - 1, x + margin); ++xx)
          near[std::size_t(yy) * std::size_t(W) + std::size_t(xx)] = 1;
    }
  return near;
}

// Cracks in a surface's triangles, against the truth: pixels away from the truth's contours
// (nearTruthContours) where the triangles show the background while the truth shows the
// surface, or, on a closed surface, show its inside (a back face, as insideViews).
inline int cracksAwayFromContours(const Scene& s, const FrameBuffer& truth, const FrameBuffer& fb,
                                  const std::vector<char>& nearContours, bool closed) {
  const Eigen::Matrix4d Minv = s.camera.worldToWindow(fb.width, fb.height).inverse();
  int n = 0;
  for (int y = 0; y < fb.height; ++y)
    for (int x = 0; x < fb.width; ++x) {
      const std::size_t i = std::size_t(y) * std::size_t(fb.width) + std::size_t(x);
      if (nearContours[i] || truth.object[i] < 0) continue;
      if (fb.object[i] < 0) {
        ++n;
        continue;
      }
      if (!closed || fb.primitive[i] < 0) continue;
      if (seenFromInside(s, fb.primitive[i], pixelPoint(Minv, x, y, fb.depth[i]))) ++n;
    }
  return n;
}

}  // namespace qacc
