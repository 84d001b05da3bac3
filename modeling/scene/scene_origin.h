// The origin of a scene's frame. A loaded scene holds every coordinate — primitives,
// camera, point lights, exact surfaces — relative to `Scene::origin` (world = scene + origin),
// so that a scene placed far from the world origin keeps the precision of one placed at it.
//
// Why: a quadric translated by t has coefficients of order |t|²; at |t| = 1e7 the constant
// term of a unit sphere carries an absolute error of 1e14 · 2⁻⁵³ ≈ 0.01, a 1 % error in its
// radius, and the window transform cancels these large terms again. Built relative to a
// nearby origin, an object's transform subtracts the origin from its translation once,
// before any quadric is formed, and the coefficients stay of the object's own size.
//
// The origin is the camera's target rounded to a multiple of g = 2^(ceil(log2 s) + 4), s the
// view's scale (eye–target distance, and the height of an orthographic view): a point within
// g/2 of the origin and the origin lie within a factor 2 of each other in every coordinate
// the origin is non-zero in, so their difference is exact (Sterbenz). A scene whose target
// lies within g/2 of the world origin — every shipped scene — keeps the origin 0, and its
// numbers are unchanged.
#pragma once
#include <Eigen/Dense>

#include "modeling/scene/camera.h"

namespace qacc {

Eigen::Vector3d sceneOrigin(const Camera& camera);

}  // namespace qacc
