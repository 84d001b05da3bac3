// Setup arithmetic (design §3.2 step 2), per primitive, in the setup processor's floating
// point: transform to window space (raster/pixel/window_primitive.h), exact screen box,
// local origin at the box corner (small coordinates), the contour conic Δ = b² − ac,
// block-exponent normalisation (Q and kQ are the same surface), 1/a, interpolator seeds
// for Δ, b, c, the clip planes, their depths (caps) and the shading vectors; then
// quantisation of all of it to the configured formats (PrimitiveSetup). Its cost in time
// is the setup unit's (timing/setup_unit.h), from the operation count below.
#pragma once
#include <Eigen/Dense>

#include "hw_model/config/hw_config.h"
#include "hw_model/datapath/fixed_point.h"
#include "hw_model/datapath/primitive_setup.h"
#include "modeling/scene/scene.h"

namespace qacc {

// The setup of primitive `index` of the scene; M is world → window, Minv its inverse.
PrimitiveSetup setupPrimitive(const Scene& scene, int index, const Eigen::Matrix4d& M, const Eigen::Matrix4d& Minv,
                              const HwConfig& cfg, OverflowCounter& ovf);
// Multiply-add operations of the setup of a primitive with `planes` clip planes and
// `pointLights` point lights (see setup_arithmetic.cpp for the breakdown).
int setupOperationCount(int planes, int pointLights, bool facet);
// The first multiply-adds of that count: the window transform of the quadric and its planes
// and the exact screen box, all a culled primitive (PrimitiveSetup::culled) costs.
int boxTestOperationCount(int planes, bool facet);
// The multiply-adds of the depth floor (PrimitiveSetup::zFloor), the z extent of the piece,
// added to the setup of a machine with the hierarchical Z unit.
int depthFloorOperationCount(int planes, bool facet);

}  // namespace qacc
