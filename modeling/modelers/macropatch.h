// Froumentin macropatches (thesis §4.4, digest §3): piecewise quadric surfaces that imitate
// quadratic Bézier triangles. A control net has 6 points in the order
//   P[0] = P1 (corner), P[1] = P2 (tangent control of edge P1-P3), P[2] = P3 (corner),
//   P[3] = P4 (control of edge P3-P5), P[4] = P5 (corner), P[5] = P6 (control of edge P5-P1).
// The corners are interpolated; the surface is tangent to the control segments at the
// corners; the tetrahedra that carry the quadrics fill the region between the corner
// triangle (P1, P3, P5) and the control triangle (P2, P4, P6). The thesis's figures of the
// layouts are missing; these are the reconstructions implemented and verified here
// (tests/test_macropatch.cpp measures every claim below).
//
// Sign convention: f <= 0 inside. The corner triangle (P1 P3 P5) is on the inside, the tangent
// controls on the outside (f > 0), so a closed net whose controls bulge outwards bounds a
// solid.  A = apex = centroid of the tangent controls (P2 + P4 + P6) / 3.
//
// Model "G0" (4 quadrics, 4 tetrahedra):
//   central (P1, P3, P5, A) and, per edge, (Pa, Pc, Pb, A) with Pa, Pb its corners and Pc its
//   control. Coefficients are constants (thesis: 0 at interpolated points and along tangent
//   segments, the others fixed or user-set):
//     corners 0; tangent segments (Pa-Pc, Pb-Pc) 0; control vertex Pc: 1; chord Pa-Pb: -2
//     (the face (Pa, Pc, Pb) then holds exactly the quadratic Bézier boundary curve
//     (1-t)² Pa + 2t(1-t) Pc + t² Pb, shared with the neighbouring macropatch, hence G0
//     between macropatches); apex A: `apex`; corner-apex edges: `corner_apex`;
//     control-apex edges: `control_apex` (defaults 1/6, 1/6, 1/2, or fitted per net to the
//     Bézier triangle with fit_g0; all >= 0 keeps the surface off the two outer faces
//     (Pa, Pc, A), (Pc, Pb, A), whose coefficients are then >= 0 and vanish only at the corner).
//   Inside the macropatch the 3 shared faces (Pa, Pb, A) get equal coefficients: G0.
//
// Model "G1" (18 quadrics, Powell-Sabin split; digest's reading):
//   M_ab = midpoint of corner edge a-b, O = centroid of the corners, m_cd = midpoint of the
//   control-triangle edge between the two controls c, d adjacent to a corner, A as above.
//   6 central tetrahedra (corner, M, O, A), 6 edge tetrahedra (corner, M, control, A),
//   6 filling tetrahedra (corner, control, m, A): the cone from A over the 7 faces of the
//   octahedron P1..P6 other than the control triangle (which contains A).
//   Constraints, imposed exactly:
//   - corners: value 0 and gradient g_v = s_v n_v, the same in every tetrahedron at the
//     corner, hence edge coefficients c(v, w) = ½ g_v·(w - v) (digest: b_ij = ½ n_i·(v_j - v_i)).
//     n_v = normalised sum of the unit normals of the control triangles (v, c, c') over all
//     nets that share the corner (exact position match); s_v = 1 / mean |c - v|.
//   - boundary faces (Pa, M, Pc) and (M, Pb, Pc): a C1 pair of conics computed only from
//     (Pa, Pb, Pc, g_a, g_b), so two macropatches sharing the edge get identical face
//     coefficients (G0 between macropatches):
//       a = ½ g_a·(M - Pa), b = ½ g_b·(M - Pb), c(M) = (a + b)/2, c(Pc) = -(a + b)/2,
//       c(Pa, M) = a, c(Pb, M) = b, all other face coefficients 0.
//     (With a == b this is exactly the Bézier boundary parabola; the split at M removes the
//     condition a == b that a single conic would impose around every corner triangle.)
//   - G1 (3.23) across all 24 internal faces.
//   The remaining freedom is fixed by a least-squares fit to the quadratic Bézier triangle
//   of the same net (f = 0 and ∇f ⟂ the Bézier tangents at sample points, each sample in
//   the tetrahedron that contains it) plus a tiny ridge term; the constraints are solved
//   exactly in their null space (SVD).
//   Between macropatches ("between": "G1", the default; the thesis notes it is very
//   constrained): the cross-boundary derivative ∇f·ν on each boundary face is also imposed
//   from shared data (ν from the sorted boundary points, g_a·ν and g_b·ν at the corners,
//   their mean at M and Pc), so both sides' quadrics differ by μ p² there: G1 across. On
//   symmetric nets (the octahedron) this determines all 180 coefficients and is consistent;
//   on general nets it is inconsistent and the build refuses with a message — use
//   "between": "G0" (boundary values only, the free coefficients fitted; corner normals
//   still shared, so G1 holds at the corners; the angle along boundaries is measured).
#pragma once
#include <array>
#include <string>
#include <vector>

#include <Eigen/Dense>

#include "modeling/modelers/bb_quadric.h"
#include "modeling/loader/object_registry.h"
#include "modeling/loader/view_cull_count.h"
#include "modeling/geometry/primitive.h"

namespace qacc {

using ControlNet = std::array<Eigen::Vector3d, 6>;

// Quadratic Bézier triangle of the net at barycentric (u, v, w) for corners (P1, P3, P5).
Eigen::Vector3d bezierTrianglePoint(const ControlNet& net, double u, double v, double w);
// Its (unnormalised) normal ∂/∂u x ∂/∂v with w = 1 - u - v, oriented away from the inside.
Eigen::Vector3d bezierTriangleNormal(const ControlNet& net, double u, double v, double w);

enum class MacropatchModel { G0, G1 };

struct MacropatchOptions {
  MacropatchModel model = MacropatchModel::G0;
  // G0 constants (see above).
  double apex = 1.0 / 6.0;
  double corner_apex = 1.0 / 6.0;
  double control_apex = 0.5;
  // G0: fit the three constants per net to its Bézier triangle instead (least squares on
  // f = 0 and tangency at sample points, constants kept >= 0). The scene builder fits
  // unless one of the constants is given.
  bool fit_g0 = false;
  // G1 fit: samples per Bézier triangle edge, weight of the normal equations, ridge term.
  int fit_samples = 12;
  double normal_weight = 1.0;
  double ridge = 1e-8;
  // G1: also impose the cross-boundary derivative on boundary faces from shared data
  // (G1 between macropatches).
  bool cross_boundary = true;
};

struct MacropatchCell {
  BBQuadric bb;
  int patch = 0;  // index of the control net
};

// All cells of all nets (4 or 18 per net). Throws std::invalid_argument for degenerate nets
// (coincident points, flat tetrahedra) or when the G1 constraints turn out inconsistent.
std::vector<MacropatchCell> buildMacropatchCells(const std::vector<ControlNet>& nets,
                                                 const MacropatchOptions& options);
// Cells as primitives (provably empty cells, whose 10 coefficients share one strict sign,
// are not emitted); `object` is stored in each primitive. With a `view` (view culling,
// ObjectContext::view), a cell whose tetrahedron misses it is not turned into a primitive
// (counted in `count`; the cells themselves are solved together, G1 across nets).
std::vector<Primitive> macropatchPrimitives(const std::vector<MacropatchCell>& cells, int material = 0,
                                            int object = 0, const ViewVolume* view = nullptr,
                                            ViewCullCount* count = nullptr);

// Continuity measured over every pair of cells that share a face (exact vertex positions):
// internal pairs (same net) and macropatch-to-macropatch pairs separately.
struct MacropatchContinuity {
  FaceContinuity internal;
  FaceContinuity external;
  int internal_faces = 0;
  int external_faces = 0;
};
MacropatchContinuity measureMacropatchContinuity(const std::vector<MacropatchCell>& cells,
                                                 int subdivisions = 16);

// Named closed control nets: "octahedron" (8 nets: corners ±r e_i, controls r(±1, ±1, 0)-type,
// so every corner's controls are coplanar — a rounded octahedron, G1-consistent at corners).
std::vector<ControlNet> namedControlNets(const std::string& name, double radius = 1.0);

// Scene builder for "macropatch": {"control_nets": [[[x,y,z] x 6], ...] | "surface": NAME,
// "radius": r (named surfaces), "model": "G0" | "G1" | "bezier", "between": "G1" | "G0" (G1
// model only), "apex", "corner_apex", "control_apex" (G0 constants; fitted when absent),
// "tessellation": n (bezier: the nets' quadratic Bézier triangles as n² triangles each)}.
std::vector<Primitive> buildMacropatch(const JsonNode& o, ObjectContext& ctx);

// Tessellation of the nets' quadratic Bézier triangles into n² triangles each (vertices
// shared along each net's edges; corner/edge positions are evaluated identically by both
// nets, so a closed net gives a closed mesh).
struct BezierMesh {
  std::vector<Eigen::Vector3d> vertices;
  std::vector<std::array<int, 3>> triangles;
};
BezierMesh tessellateBezierTriangles(const std::vector<ControlNet>& nets, int n);

}  // namespace qacc
