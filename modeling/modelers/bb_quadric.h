// Bernstein-Bézier (BB) quadric patch on a tetrahedron (thesis (3.14)-(3.16), (3.23);
// digest §2).
//
// Vertices V0..V3 (the thesis's V1..V4). A point X = Σ λa Va with Σ λa = 1 (barycentric
// coordinates λ = (λ0, λ1, λ2, λ3)). The BB form (3.14) is
//     f(λ) = Σ_{i+j+k+l=2} 2/(i! j! k! l!) c_ijkl λ0^i λ1^j λ2^k λ3^l
//          = λᵀ C λ
// where C is the symmetric 4x4 "coefficient matrix":
//     C(a, a) = vertex coefficient at Va      (c_2000 = C(0,0), c_0200 = C(1,1), ...)
//     C(a, b) = edge coefficient of edge VaVb (c_1100 = C(0,1), c_1010 = C(0,2), c_0011 = C(2,3), ...)
// i.e. the multi-index (i, j, k, l) names the coefficient sitting at the barycentric
// position (i, j, k, l)/2; index i goes with V0, j with V1, k with V2, l with V3.
//
// Convention (checked against the corrected sphere example of the digest, see
// tests/test_bb_quadric.cpp): V is the 4x4 matrix whose ROW a is (Va.x, Va.y, Va.z, 1), so
// the homogeneous point is X = Vᵀ λ and, with the Cartesian quadric matrix M = Q of
// modeling/quadric.h (f = Xᵀ Q X),
//     C = V Q Vᵀ            (3.16)
//     Q = V⁻¹ C V⁻ᵀ         (3.15)
// For the unit sphere Q = diag(1,1,1,-1) on V = (0,0,0),(1,0,0),(0,1,0),(0,0,1) this gives
// C = [[-1,-1,-1,-1],[-1,0,-1,-1],[-1,-1,0,-1],[-1,-1,-1,0]]; vertex coefficients are f(Va).
// The Cartesian value and the BB value agree exactly (not up to scale), so the sign
// convention of Quadric (solid interior f <= 0) carries over to the patch.
//
// Properties used by the modelers:
//  - the patch passes through Va iff C(a,a) == 0; it is tangent to edge VaVb at Va iff
//    additionally C(a,b) == 0 (the derivative along the edge at Va is 2 (C(a,b) - C(a,a)));
//  - convex hull: if all 10 coefficients have one strict sign the surface misses the
//    closed tetrahedron (isProvablyEmpty) and the cell need not be emitted;
//  - G0 across a shared face: equal face coefficients (the 6 with zero index on the free
//    vertex); G1 (3.23, Dahmen): additionally, for each shared vertex Va,
//    c'(a, free') = Σ_b λb C(a, b) with λ the barycentric coordinates of the neighbour's
//    free vertex in this tetrahedron. The two polynomials then differ by μ·p² with p the
//    shared face's plane, so values and gradients agree on the whole face (same normal
//    direction and orientation). 9 of the neighbour's 10 coefficients are fixed; the one
//    at its free vertex stays free.
#pragma once
#include <array>
#include <vector>

#include <Eigen/Dense>

#include "modeling/geometry/half_space.h"
#include "modeling/geometry/primitive.h"
#include "modeling/geometry/quadric.h"

namespace qacc {

using Tetrahedron = std::array<Eigen::Vector3d, 4>;

struct BBQuadric {
  Tetrahedron V;                            // V0..V3
  Eigen::Matrix4d C = Eigen::Matrix4d::Zero();  // symmetric coefficient matrix (see above)

  BBQuadric() = default;
  BBQuadric(const Tetrahedron& v, const Eigen::Matrix4d& c) : V(v), C(0.5 * (c + c.transpose())) {}

  // Matrix of rows (Va.x, Va.y, Va.z, 1).
  static Eigen::Matrix4d vertexMatrix(const Tetrahedron& v);
  // Signed volume of the tetrahedron (positive when (V1-V0, V2-V0, V3-V0) is right-handed).
  static double signedVolume(const Tetrahedron& v);

  // (3.16) C = V Q Vᵀ.
  static BBQuadric fromQuadric(const Quadric& q, const Tetrahedron& v);
  // (3.15) Q = V⁻¹ C V⁻ᵀ. Throws std::invalid_argument for a degenerate tetrahedron.
  Quadric toQuadric() const;

  // Coefficient c_ijkl (i + j + k + l == 2, all >= 0); throws std::invalid_argument otherwise.
  double coefficient(int i, int j, int k, int l) const;
  void setCoefficient(int i, int j, int k, int l, double value);
  // The 10 multi-indices in a fixed order: 2000,0200,0020,0002,1100,1010,1001,0110,0101,0011.
  static const std::array<std::array<int, 4>, 10>& multiIndices();

  // Barycentric coordinates of p (sum 1). Throws for a degenerate tetrahedron.
  Eigen::Vector4d barycentric(const Eigen::Vector3d& p) const;
  Eigen::Vector3d point(const Eigen::Vector4d& lambda) const;
  // λᵀ C λ (the BB sum (3.14)); equals toQuadric().eval(point(λ)) when Σ λ = 1.
  double evalBarycentric(const Eigen::Vector4d& lambda) const { return lambda.dot(C * lambda); }
  double eval(const Eigen::Vector3d& p) const { return evalBarycentric(barycentric(p)); }

  // All 10 coefficients > 0, or all < 0: no surface point in the closed tetrahedron.
  bool isProvablyEmpty() const;

  // Half-space of the face opposite Va, keeping the tetrahedron's side (see facePlane).
  HalfSpace faceHalfSpace(int a) const;
  // The patch as a Primitive clipped by the 4 faces. Faces are built by facePlane, so a
  // face shared with a neighbouring tetrahedron gets exactly the opposite half-space there
  // (one plane, and its opposite()): exactly one of the two cells owns the boundary.
  Primitive toPrimitive(int material = 0, int object = 0, bool solid = false) const;
};

// The plane through a, b, c as (n, -n·p0) with n = (p1 - p0) x (p2 - p0), the points sorted
// lexicographically: every caller that names the same three points (in any order) gets
// bit-identical coefficients. Zero for a degenerate triangle.
Eigen::Vector4d canonicalPlane(const Eigen::Vector3d& a, const Eigen::Vector3d& b, const Eigen::Vector3d& c);
// Canonical half-space of the plane through a, b, c keeping the side of `inside` (which
// must not lie on the plane). The plane's coefficients are computed from the three points
// sorted lexicographically, so every caller that names the same three points (in any
// order) gets bit-identical coefficients, either p or -p = HalfSpace(p).opposite().
HalfSpace facePlane(const Eigen::Vector3d& a, const Eigen::Vector3d& b, const Eigen::Vector3d& c,
                    const Eigen::Vector3d& inside);

// Correspondence between two tetrahedra sharing one face (3 vertices at equal positions).
struct SharedFace {
  std::array<int, 3> a;  // indices of the shared vertices in the first tetrahedron
  std::array<int, 3> b;  // the same vertices in the second one (b[k] matches a[k])
  int free_a = -1;       // the vertex of the first not on the face
  int free_b = -1;       // the vertex of the second not on the face
};
// Finds the shared face by exact position equality; throws std::invalid_argument if the
// two tetrahedra do not share exactly three vertices.
SharedFace findSharedFace(const Tetrahedron& first, const Tetrahedron& second);

// G0 join: copies the 6 face coefficients of `patch` onto the shared face of `neighbour`
// (its other 4 coefficients are left unchanged).
void joinG0(const BBQuadric& patch, BBQuadric& neighbour);
// G1 join (3.23): G0 plus the 3 coefficients on the edges from the shared vertices to the
// neighbour's free vertex; only the neighbour's free-vertex coefficient stays free.
void joinG1(const BBQuadric& patch, BBQuadric& neighbour);

// Continuity measured on a shared face (a, b, c) between the quadrics of two cells.
//  - values: on a grid of barycentric samples covering the face (corners and edges included),
//    max |f1 - f2| relative to (largest |∇f1| on the face) x (face diameter);
//  - normals on the face: angle between ∇f1 and ∇f2 (degrees) at every sample where both
//    gradients exceed `min_gradient` x the largest gradient on the face (G1 makes this 0
//    everywhere on the face, not only on the surface);
//  - normals on the surface: the same angle at the points where the surface f1 = 0 crosses
//    the face (found by bisection along the grid's segments), which is what a viewer sees.
struct FaceContinuity {
  double max_value_diff = 0;
  double max_angle_face_deg = 0;
  double max_angle_surface_deg = 0;
  int samples = 0;
  int surface_points = 0;
};
FaceContinuity measureFaceContinuity(const Quadric& q1, const Quadric& q2, const Eigen::Vector3d& a,
                                     const Eigen::Vector3d& b, const Eigen::Vector3d& c,
                                     int subdivisions = 16, double min_gradient = 1e-3);
// Accumulates the worst of two measurements.
void mergeContinuity(FaceContinuity& into, const FaceContinuity& other);

}  // namespace qacc
