// The scene's view as a screen sees it: how many pixels a distance at a point covers in the
// image, projection and on-screen tests (used by view-dependent tessellation, tessellation/
// screen_error.h, and by the loader's check of an object frame's precision).
//
// Perspective: a displacement d at eye-space point (X, Y, −Z) moves the image point by at
// most  f |p − eye| / Z² · |d|  pixels (f = height / (2 tan(fov_y / 2)), the focal length
// in pixels; the largest singular value of the Jacobian of (X/Z, Y/Z) is √(1 + (X²+Y²)/Z²)
// / Z). Orthographic: f = height / view height, constant. Depths are clamped to the near
// plane (nothing nearer is drawn).
#pragma once
#include <Eigen/Dense>

#include "modeling/scene/camera.h"

namespace qacc {

class ScreenView {
 public:
  Camera camera;
  int width = 640, height = 480;
  Eigen::Matrix4d view;    // world → eye
  Eigen::Matrix4d window;  // world → window (homogeneous)
  double focal = 1;        // pixels per unit of X/Z (perspective) or per world unit (orthographic)

  ScreenView(const Camera& camera, int width, int height);

  // Pixels per world unit at p (an upper bound over directions).
  double pixelsPerUnit(const Eigen::Vector3d& p) const;
  // An upper bound of pixelsPerUnit over a box.
  double maxPixelsPerUnit(const Eigen::AlignedBox3d& box) const;
  // Whether the window point of p lies in front of the eye, between the near and far planes
  // and within `margin` pixels of the image.
  bool onScreen(const Eigen::Vector3d& p, double margin) const;
  // Whether p is beyond the near plane (its depth can be drawn).
  bool inFront(const Eigen::Vector3d& p) const;
  // (x, y) window position; valid when p is in front of the eye.
  Eigen::Vector2d project(const Eigen::Vector3d& p) const;
  // Whether any part of the box can be on screen (conservative: its projected corners'
  // extent against the image, widened by `margin` pixels; boxes reaching behind the eye
  // count as on screen).
  bool boxOnScreen(const Eigen::AlignedBox3d& box, double margin) const;
};

}  // namespace qacc
