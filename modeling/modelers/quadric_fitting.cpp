#include "modeling/modelers/quadric_fitting.h"

#include <cmath>
#include <limits>
#include <stdexcept>

namespace qacc {

namespace {

using Eigen::Matrix4d;
using Eigen::MatrixXd;
using Eigen::Vector3d;
using Eigen::VectorXd;

Matrix4d sym(int i, int j) {
  Matrix4d m = Matrix4d::Zero();
  if (i == j) {
    m(i, i) = 1.0;
  } else {
    m(i, j) = m(j, i) = 0.5;  // so that Xᵀ m X = X_i X_j
  }
  return m;
}

// Solves M a = 0 by SVD and fills the common result fields.
void solveHomogeneous(const MatrixXd& Min, const std::vector<Matrix4d>& basis, double tol, InterpolationResult& r) {
  MatrixXd M = Min;
  for (Eigen::Index i = 0; i < M.rows(); ++i) {
    const double n = M.row(i).norm();
    if (n > 0) M.row(i) /= n;
  }
  const Eigen::Index m = Eigen::Index(basis.size());
  r.equations = int(M.rows());
  // Pad to at least m rows so the full right singular basis is available.
  MatrixXd A = MatrixXd::Zero(std::max<Eigen::Index>(M.rows(), m), m);
  A.topRows(M.rows()) = M;
  Eigen::JacobiSVD<MatrixXd> svd(A, Eigen::ComputeFullV);
  r.singular_values = svd.singularValues();
  const double smax = r.singular_values.size() ? r.singular_values[0] : 0.0;
  r.dimension = 0;
  for (Eigen::Index k = 0; k < m; ++k)
    if (r.singular_values[k] <= tol * std::max(smax, 1e-300)) ++r.dimension;
  auto toQuadric = [&](const VectorXd& a) {
    Matrix4d Q = Matrix4d::Zero();
    for (Eigen::Index k = 0; k < m; ++k) Q += a[k] * basis[std::size_t(k)];
    return Quadric(Q);
  };
  r.solution_space.clear();
  for (int k = 0; k < r.dimension; ++k) r.solution_space.push_back(toQuadric(svd.matrixV().col(m - 1 - k)));
  const VectorXd best = svd.matrixV().col(m - 1);
  r.quadric = toQuadric(best);
  r.residual = (M * best).norm() / std::max(M.norm(), 1e-300);
}

}  // namespace

std::vector<Matrix4d> familyBasis(QuadricFamily family) {
  switch (family) {
    case QuadricFamily::General: {
      std::vector<Matrix4d> b;
      for (int i = 0; i < 4; ++i)
        for (int j = i; j < 4; ++j) b.push_back(sym(i, j));
      return b;
    }
    case QuadricFamily::Sphere:
      return {Matrix4d(sym(0, 0) + sym(1, 1) + sym(2, 2)), sym(0, 3), sym(1, 3), sym(2, 3), sym(3, 3)};
    case QuadricFamily::AxisAligned:
      return {sym(0, 0), sym(1, 1), sym(2, 2), sym(0, 3), sym(1, 3), sym(2, 3), sym(3, 3)};
    case QuadricFamily::RevolutionZ:
      return {Matrix4d(sym(0, 0) + sym(1, 1)), sym(2, 2), sym(2, 3), sym(3, 3)};
  }
  throw std::invalid_argument("unknown quadric family");
}

std::string familyName(QuadricFamily family) {
  switch (family) {
    case QuadricFamily::General: return "general";
    case QuadricFamily::Sphere: return "sphere";
    case QuadricFamily::AxisAligned: return "axis-aligned";
    case QuadricFamily::RevolutionZ: return "revolution-z";
  }
  return "?";
}

InterpolationResult interpolatePoints(const std::vector<Vector3d>& points, QuadricFamily family, double tol) {
  const auto basis = familyBasis(family);
  MatrixXd M(Eigen::Index(points.size()), Eigen::Index(basis.size()));
  for (std::size_t i = 0; i < points.size(); ++i) {
    const Eigen::Vector4d X = points[i].homogeneous();
    for (std::size_t k = 0; k < basis.size(); ++k) M(Eigen::Index(i), Eigen::Index(k)) = X.dot(basis[k] * X);
  }
  InterpolationResult r;
  solveHomogeneous(M, basis, tol, r);
  return r;
}

PointNormalResult interpolatePointNormals(const std::vector<Vector3d>& points, const std::vector<Vector3d>& normals,
                                          QuadricFamily family, double tol) {
  if (points.size() != normals.size()) throw std::invalid_argument("as many normals as points are needed");
  const auto basis = familyBasis(family);
  const Eigen::Index m = Eigen::Index(basis.size());
  MatrixXd M(Eigen::Index(3 * points.size()), m);
  for (std::size_t i = 0; i < points.size(); ++i) {
    const Vector3d n = normals[i];
    if (!(n.norm() > 0)) throw std::invalid_argument("zero normal");
    // Two tangents orthogonal to n.
    const Vector3d helper = std::abs(n.x()) < 0.9 * n.norm() ? Vector3d::UnitX() : Vector3d::UnitY();
    const Vector3d t1 = n.cross(helper).normalized(), t2 = n.normalized().cross(t1);
    const Eigen::Vector4d X = points[i].homogeneous();
    for (Eigen::Index k = 0; k < m; ++k) {
      const Matrix4d& B = basis[std::size_t(k)];
      const Vector3d g = 2.0 * (B * X).head<3>();
      M(Eigen::Index(3 * i), k) = X.dot(B * X);
      M(Eigen::Index(3 * i + 1), k) = g.dot(t1);
      M(Eigen::Index(3 * i + 2), k) = g.dot(t2);
    }
  }
  PointNormalResult r;
  solveHomogeneous(M, basis, tol, r);
  double gmax = 0, gmin = std::numeric_limits<double>::infinity(), worst = 0;
  for (std::size_t i = 0; i < points.size(); ++i) {
    const Vector3d g = r.quadric.gradient(points[i]);
    gmax = std::max(gmax, g.norm());
    gmin = std::min(gmin, g.norm());
    if (g.norm() > 0) {
      const Vector3d a = g.normalized(), b = normals[i].normalized();
      worst = std::max(worst, std::atan2(a.cross(b).norm(), std::abs(a.dot(b))) * 180.0 / M_PI);
    } else {
      worst = 90.0;
    }
  }
  r.min_gradient_ratio = gmax > 0 ? gmin / gmax : 0.0;
  r.worst_normal_angle_deg = worst;
  r.tangent_planes_ok = r.dimension >= 1 && r.min_gradient_ratio > 1e-6 && worst < 1e-6 * 180.0 / M_PI;
  return r;
}

GuoCondition guoTangentPlanesCondition(const std::array<Vector3d, 3>& P, const std::array<Vector3d, 3>& N, double tol) {
  GuoCondition g;
  auto Pij = [&](int i, int j) { return Vector3d(P[std::size_t(j)] - P[std::size_t(i)]); };
  auto orth = [&](int i, int j) {
    const Vector3d e = Pij(i, j);
    return std::abs(N[std::size_t(i)].dot(e)) <= tol * N[std::size_t(i)].norm() * e.norm() &&
           std::abs(N[std::size_t(j)].dot(e)) <= tol * N[std::size_t(j)].norm() * e.norm();
  };
  if (orth(0, 1) || orth(1, 2) || orth(2, 0)) {
    g.orthogonal_case = true;
    g.holds = true;
  }
  const double d1 = Pij(0, 2).dot(N[0]), d2 = Pij(1, 0).dot(N[1]), d3 = Pij(2, 1).dot(N[2]);
  if (d1 == 0 || d2 == 0 || d3 == 0) {
    g.product = std::numeric_limits<double>::quiet_NaN();
    return g;
  }
  g.product = (Pij(0, 1).dot(N[0]) / d1) * (Pij(1, 2).dot(N[1]) / d2) * (Pij(2, 0).dot(N[2]) / d3);
  if (std::abs(g.product - 1.0) <= tol * 1e3) g.holds = true;
  return g;
}

}  // namespace qacc
