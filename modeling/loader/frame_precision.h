// The precision an object's own frame gives away (docs/SCENES.md, "Scenes far from the world
// origin"). The loader holds a scene near its view (scene/scene_origin.h), which keeps every
// object placed by `transform` exact; an object whose data itself lies far from its frame's
// origin (a `center` of 1e7, a PDB file in such coordinates, a `quadric` matrix) forms its
// quadric there, with coefficients of order D², D the distance: its surface is then known only
// to about 2⁻⁵² (D + r)² / r frame units (r its half size) — the rounding of the constant term
// over the gradient. The loader refuses an object whose surface that leaves uncertain by more
// than kMaxFrameErrorPixels on screen, rather than let the reference (the ground truth of
// every metric) draw it wrong.
#pragma once
#include <Eigen/Dense>

#include "modeling/scene/screen_view.h"

namespace qacc {

constexpr double kMaxFrameErrorPixels = 1.0 / 16;

class FramePrecision {
 public:
  // `placement`: the object's frame → scene frame (its transform with the scene's origin taken out).
  FramePrecision(const Eigen::Matrix4d& placement, const ScreenView& view);
  // Upper estimate of the on-screen uncertainty, in pixels, of a piece whose scene-frame
  // bounds are `box`.
  double pixels(const Eigen::AlignedBox3d& box) const;

 private:
  Eigen::Matrix4d inverse_;
  double stretch_ = 1;  // largest singular value of the placement's linear part
  const ScreenView& view_;
};

}  // namespace qacc
