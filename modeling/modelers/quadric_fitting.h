// Quadric interpolation (thesis §4.3, digest §3): Pratt's linear method on a basis of a
// quadric family, Bajaj-Ihm point/normal interpolation by SVD, Guo's Tangent Planes
// Condition (4.14).
//
// Every method builds a homogeneous linear system M a = 0 on the coefficients a of a
// family basis (Q = Σ a_k B_k) and solves it by SVD: the solution space is spanned by the
// right singular vectors whose singular value is <= tol x the largest one. Its dimension
// says whether the data define the quadric (1), under-determine it (> 1) or are
// inconsistent for the family (0: the best least-squares quadric, i.e. the last singular
// vector, is returned with its residual).
#pragma once
#include <array>
#include <string>
#include <vector>

#include <Eigen/Dense>

#include "modeling/geometry/quadric.h"

namespace qacc {

enum class QuadricFamily {
  General,       // 10 coefficients: 9 points in general position
  Sphere,        // (x² + y² + z²), x, y, z, 1: 4 points
  AxisAligned,   // x², y², z², x, y, z, 1 (ellipsoids, hyperboloids... with axes along x, y, z): 6 points
  RevolutionZ,   // (x² + y²), z², z, 1 about the z axis: 3 points
};
std::vector<Eigen::Matrix4d> familyBasis(QuadricFamily family);
std::string familyName(QuadricFamily family);

struct InterpolationResult {
  Quadric quadric;                       // a solution (the first basis vector of the space)
  std::vector<Quadric> solution_space;   // basis of the solution space (empty if dimension 0)
  int dimension = 0;                     // dimension of the solution space
  int equations = 0;
  double residual = 0;                   // ||M a|| / ||M|| for the returned quadric (|a| = 1)
  Eigen::VectorXd singular_values;       // of the (row-normalised) system, descending
};

// Pratt: f(p_i) = 0 for every point, on the family's basis.
InterpolationResult interpolatePoints(const std::vector<Eigen::Vector3d>& points,
                                      QuadricFamily family = QuadricFamily::General, double tol = 1e-9);

// Bajaj-Ihm: f(p_i) = 0 and ∇f(p_i) ∥ n_i (∇f·t = 0 for two tangents t ⟂ n_i): 3 equations
// per pair; 3 pairs nominally define a general quadric (9 equations, 10 unknowns).
// The result also says whether the solution really has the prescribed tangent planes
// (non-zero gradients parallel to the normals) — a degenerate solution (gradient 0 at a
// point) satisfies the linear system without doing so; see Guo's condition below.
struct PointNormalResult : InterpolationResult {
  bool tangent_planes_ok = false;  // every |∇f(p_i)| > 1e-6 x max and parallel to n_i within 1e-6 rad
  double worst_normal_angle_deg = 0;
  double min_gradient_ratio = 0;   // min |∇f(p_i)| / max |∇f(p_i)|
};
PointNormalResult interpolatePointNormals(const std::vector<Eigen::Vector3d>& points,
                                          const std::vector<Eigen::Vector3d>& normals,
                                          QuadricFamily family = QuadricFamily::General, double tol = 1e-9);

// Guo's Tangent Planes Condition (4.14) for three point/normal pairs: a (non-degenerate)
// quadric through P1, P2, P3 with normals N1, N2, N3 exists iff two normals are orthogonal
// to their shared edge, or (P12·N1 / P13·N1)(P23·N2 / P21·N2)(P31·N3 / P32·N3) = 1 with
// Pij = Pj - Pi. "= 1" and "orthogonal" are tested with relative tolerances 1e3·tol and tol.
struct GuoCondition {
  bool holds = false;
  bool orthogonal_case = false;  // two normals orthogonal to their shared edge
  double product = 0;            // the product (NaN if a denominator is 0)
};
GuoCondition guoTangentPlanesCondition(const std::array<Eigen::Vector3d, 3>& P,
                                       const std::array<Eigen::Vector3d, 3>& N, double tol = 1e-9);

}  // namespace qacc
