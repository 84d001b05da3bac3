// The per-direction densities of a natural quadric's parametric grid for a screen-space
// error (tessellation.h, `pixel_error`): u (around the axis) and v (along it, or the polar
// angle) get their own step from the projected curvature of the surface in that direction.
//
// A grid step Δ = (Δu, Δv) in parameter space has the chord error (the distance from the
// chord's midpoint to the surface) ≈ |II(Δ)| / 8, where II is the second fundamental form,
// II(Δ) = L Δu² + 2 M Δu Δv + N Δv² with L = P_uᵀ H P_u / |∇f| (H the Hessian of the
// implicit f: along a surface curve ∇f·P'' = −P'ᵀ H P'), and likewise M, N. The sagitta is
// the largest error of a triangle of the grid (the interpolation error of a quadratic is
// largest on an edge or at the circumcentre, on the longest edge for the right triangles of a
// grid quad), and |II(Δ)| <= (|L|+|M|) Δu² + (|N|+|M|) Δv². Projected, a world distance d at
// p covers at most s(p) d pixels (screen_error.h). So with A_u = max s (|L|+|M|) and
// A_v = max s (|N|+|M|) over the visible part of the piece, the steps
//   Δu = √(8 (ε/2) / A_u),  Δv = √(8 (ε/2) / A_v)
// bound the projected chord error of every grid triangle by ε (to second order; the
// tessellator measures the result and refines when the neglected terms matter).
#pragma once
#include <vector>

#include "modeling/geometry/half_space.h"
#include "modeling/geometry/quadric.h"
#include "modeling/tessellation/parametric_grid.h"
#include "modeling/tessellation/surface_clipping.h"

namespace qacc {
class ScreenView;
}

namespace qacc::tess {

// The largest projected curvatures of a grid's domain over [0, 2π] x [v0, v1], sampled on a
// probe grid: over the samples kept by `planes` and on screen, or when there are none over
// those kept by `planes` in front of the near plane, or else over all in front of it; `seen`
// is false when no sample is in front of the near plane (nothing to refine for).
struct ProjectedCurvature {
  double au = 0, av = 0;  // pixels per unit parameter², in u and v
  bool seen = false;
};
ProjectedCurvature projectedCurvature(const Domain& domain, const Quadric& q, double v0, double v1,
                                      const std::vector<HalfSpace>& planes, const ScreenView& view);

// Grid counts (nu around, nv along) for a projected chord error of at most `epsilon` pixels,
// from the curvature; `scale` >= 1 multiplies both counts (the tessellator's refinement).
Grid gridForPixelError(const ProjectedCurvature& c, double v0, double v1, double epsilon, double scale = 1.0);

}  // namespace qacc::tess
