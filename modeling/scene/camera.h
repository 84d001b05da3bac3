// Camera and the world → window matrices (design §2).
// Window space: x right, y down, pixel (i, j) centred at (i + 0.5, j + 0.5); z is
// OpenGL-style window depth in [0, 1], 0 at the near plane. The world → window map is
// Viewport · Projection · View, a projective 4x4: a window point is (M X) / w.
#pragma once
#include <Eigen/Dense>

namespace qacc {

struct Camera {
  enum class Type { Perspective, Orthographic };
  Type type = Type::Perspective;
  Eigen::Vector3d eye{0, 0, 5};
  Eigen::Vector3d target{0, 0, 0};
  Eigen::Vector3d up{0, 1, 0};
  double fov_y_deg = 40.0;  // perspective: vertical field of view
  double height = 2.0;      // orthographic: world units visible vertically
  double near = 0.1;
  double far = 100.0;

  // World → eye (right-handed, looking down -z).
  Eigen::Matrix4d view() const;
  // Eye → clip, OpenGL conventions (glFrustum / glOrtho with symmetric extents).
  Eigen::Matrix4d projection(double aspect) const;
  // Clip → window for a width x height image (y down, z in [0, 1]).
  static Eigen::Matrix4d viewport(int width, int height);
  // World → window (homogeneous).
  Eigen::Matrix4d worldToWindow(int width, int height) const;

  // Unit vector from the eye towards the target.
  Eigen::Vector3d forward() const { return (target - eye).normalized(); }
  // Unit vector from a world point towards the viewer (constant for orthographic).
  Eigen::Vector3d toViewer(const Eigen::Vector3d& p) const;
};

}  // namespace qacc
