// PrimitiveSetup: everything the setup unit hands to traversal and the pixel pipelines for
// one primitive — the quantised constants and interpolator seeds, in the configured
// formats (design §3.2 step 2). Produced by setupPrimitive (setup_arithmetic.h), consumed identically by the
// functional (`hw`) and the cycle-level (`hw-cycle`) engines.
//
// Scales (Fi = interp_frac_bits, Fz = depth_frac_bits):
//   (the quadric datapath's depth variable is t = (z - z0) 2^zShift, see z0 below)
//   a                         integer at 2^e                 (block exponent e of a, b, c)
//   b(u, v), c(u, v)           interpolators at 2^(e + Fi)   (outputs >> Fi: at 2^e)
//   Δ(u, v)                    interpolator at 2^(2 ed + Fi) (block exponent ed of Δ)
//   plane h(u, v), pz          at 2^(ep + Fi)  (value at depth z: (h << Fz) + pz · z)
//   plane depth zk(u, v)       at 2^(Fz + Fi)
//   facet depth z(u, v)        at 2^(Fz + Fi)
//   shading vectors            per vector block exponent; (uv << Fz) + cz · z
#pragma once
#include <vector>

#include "hw_model/datapath/linear_interpolator.h"
#include "hw_model/datapath/quadratic_interpolator.h"

namespace qacc {

struct PlaneSetup {
  LinearCoefficients h;   // plane value without the z term
  i128 pz = 0;            // z coefficient (0 for a plane parallel to the lines of sight)
  int zdir = 0;           // sign of pz: -1 lower bound on z, +1 upper bound, 0 parallel
  LinearCoefficients zk;  // the plane's depth at the pixel (solids: caps), if zdir != 0
  bool owns = false;      // boundary ownership (half_space.h)
  i128 capNormal[3] = {0, 0, 0};  // world normal of the cap on this plane
};

// An affine vector field V(u, v, z) = uv(u, v) + cz · z (3 components).
struct VectorSetup {
  LinearCoefficients uv[3];
  i128 cz[3] = {0, 0, 0};
};

struct PrimitiveSetup {
  int index = 0, object = 0, material = 0;
  bool solid = false;
  bool visible = false;  // non-empty box and representable
  // Host culling: the exact screen box (raster/pixel/window_primitive.h) is empty — the
  // piece misses the screen or the depth range [0, 1]. The primitive is dropped after the
  // host interface, before the rest of setup; it costs the box test's operations only.
  bool culled = false;
  bool facet = false;    // flat-facet path (plane + edges, no square root)
  // The depth floor (depth format, >= 0): the depth unit never returns a visible depth below
  // it (PixelDatapath::evaluate clamps, counted in OverflowCounters::depth_floor_clamps), so it
  // is a true lower bound of every depth the datapath produces for this primitive, the bound the
  // hierarchical Z unit compares (datapath/hierarchical_z_memory.h). It is the exact minimum
  // window depth of the clipped piece (raster/pixel/window_primitive.h, pieceDepthRange) less a
  // margin for the datapath's rounding (setup_arithmetic.cpp, depthFloor), so the clamp never
  // acts where the datapath is accurate: it only moves a depth that fell below the piece itself.
  i128 zFloor = 0;
  int x0 = 0, y0 = 0, x1 = 0, y1 = 0;  // screen box [x0, x1) x [y0, y1); local origin (x0, y0)
  // Traversal: the contour conic in local coordinates (unquantised; spans are widened).
  double tA = 0, tB = 0, tC = 0, tD = 0, tE = 0, tF = 0;  // A u² + B uv + C v² + D u + E v + F
  bool fullRows = false;  // caps or facets can show where Δ < 0: issue whole rows
  // Quadric datapath.
  // Local depth origin and scale of the quadric datapath: a, b, c describe the quadric in
  // t = (z - z0) 2^zShift, so that over the primitive's own depth range t spans about
  // [-1, 1] and a, b and c are commensurate. With z itself (z in [0, 1], a perspective
  // squeezing every object to a thin slab near 1) f(z) = a z² + 2 b z + c is a difference of
  // nearly equal terms and a narrow value_bits quantises it to noise (solids turned into caps).
  i128 z0 = 0;     // depth format (2^Fz)
  int zShift = 0;  // the scale 2^-zShift of t, >= 0
  int e = 0, ed = 0;
  i128 a = 0;
  int aSign = 0;
  QuadraticCoefficients delta, c;
  LinearCoefficients b;
  i128 recipM = 0;  // reciprocal variant: 1/a ≈ recipM · 2^-recipShift (scale-free)
  int recipShift = 0;
  bool recipValid = false;
  // Facet datapath.
  LinearCoefficients facetZ;
  std::vector<PlaneSetup> planes;
  // Shading.
  VectorSetup normal, view;
  bool viewConstant = false;  // orthographic
  std::vector<VectorSetup> pointLights;  // one per point light of the scene
  // Cost.
  int setupOps = 0;
  int boxTestOps = 0;  // the part of setupOps that decides culling (window transform + exact box)
  int descriptorWords = 0;
};

}  // namespace qacc
