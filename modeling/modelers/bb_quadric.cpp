#include "modeling/modelers/bb_quadric.h"

#include <algorithm>
#include <cmath>
#include <stdexcept>

namespace qacc {

namespace {

// (i, j, k, l) with sum 2 → the matrix entry (a, b) of C.
std::pair<int, int> entryOf(int i, int j, int k, int l) {
  const int idx[4] = {i, j, k, l};
  int sum = 0;
  for (int v : idx) {
    if (v < 0 || v > 2) throw std::invalid_argument("BB multi-index entries must be 0, 1 or 2");
    sum += v;
  }
  if (sum != 2) throw std::invalid_argument("BB multi-index must sum to 2");
  int first = -1, second = -1;
  for (int a = 0; a < 4; ++a) {
    if (idx[a] == 2) return {a, a};
    if (idx[a] == 1) (first < 0 ? first : second) = a;
  }
  return {first, second};
}

bool lexLess(const Eigen::Vector3d& p, const Eigen::Vector3d& q) {
  if (p.x() != q.x()) return p.x() < q.x();
  if (p.y() != q.y()) return p.y() < q.y();
  return p.z() < q.z();
}

double angleDeg(const Eigen::Vector3d& u, const Eigen::Vector3d& v) {
  const double c = u.normalized().dot(v.normalized());
  // atan2 of |u x v| and u·v is accurate at small angles.
  const double s = u.normalized().cross(v.normalized()).norm();
  return std::atan2(s, c) * 180.0 / M_PI;
}

}  // namespace

Eigen::Matrix4d BBQuadric::vertexMatrix(const Tetrahedron& v) {
  Eigen::Matrix4d m;
  for (int a = 0; a < 4; ++a) m.row(a) << v[a].x(), v[a].y(), v[a].z(), 1.0;
  return m;
}

double BBQuadric::signedVolume(const Tetrahedron& v) {
  return (v[1] - v[0]).cross(v[2] - v[0]).dot(v[3] - v[0]) / 6.0;
}

BBQuadric BBQuadric::fromQuadric(const Quadric& q, const Tetrahedron& v) {
  const Eigen::Matrix4d Vm = vertexMatrix(v);
  return BBQuadric(v, Vm * q.Q * Vm.transpose());
}

Quadric BBQuadric::toQuadric() const {
  const Eigen::Matrix4d Vm = vertexMatrix(V);
  Eigen::FullPivLU<Eigen::Matrix4d> lu(Vm);
  if (!lu.isInvertible()) throw std::invalid_argument("BB patch on a degenerate tetrahedron");
  const Eigen::Matrix4d Vi = lu.inverse();
  return Quadric(Eigen::Matrix4d(Vi * C * Vi.transpose()));
}

double BBQuadric::coefficient(int i, int j, int k, int l) const {
  const auto e = entryOf(i, j, k, l);
  return C(e.first, e.second);
}

void BBQuadric::setCoefficient(int i, int j, int k, int l, double value) {
  const auto e = entryOf(i, j, k, l);
  C(e.first, e.second) = value;
  C(e.second, e.first) = value;
}

const std::array<std::array<int, 4>, 10>& BBQuadric::multiIndices() {
  static const std::array<std::array<int, 4>, 10> idx = {{{2, 0, 0, 0},
                                                          {0, 2, 0, 0},
                                                          {0, 0, 2, 0},
                                                          {0, 0, 0, 2},
                                                          {1, 1, 0, 0},
                                                          {1, 0, 1, 0},
                                                          {1, 0, 0, 1},
                                                          {0, 1, 1, 0},
                                                          {0, 1, 0, 1},
                                                          {0, 0, 1, 1}}};
  return idx;
}

Eigen::Vector4d BBQuadric::barycentric(const Eigen::Vector3d& p) const {
  // X = Vᵀ λ  ⇒  λ = V⁻ᵀ X.
  Eigen::FullPivLU<Eigen::Matrix4d> lu(Eigen::Matrix4d(vertexMatrix(V).transpose()));
  if (!lu.isInvertible()) throw std::invalid_argument("barycentric coordinates in a degenerate tetrahedron");
  return lu.solve(p.homogeneous());
}

Eigen::Vector3d BBQuadric::point(const Eigen::Vector4d& lambda) const {
  return lambda[0] * V[0] + lambda[1] * V[1] + lambda[2] * V[2] + lambda[3] * V[3];
}

bool BBQuadric::isProvablyEmpty() const {
  bool all_pos = true, all_neg = true;
  for (int a = 0; a < 4; ++a)
    for (int b = a; b < 4; ++b) {
      all_pos = all_pos && C(a, b) > 0.0;
      all_neg = all_neg && C(a, b) < 0.0;
    }
  return all_pos || all_neg;
}

Eigen::Vector4d canonicalPlane(const Eigen::Vector3d& a, const Eigen::Vector3d& b, const Eigen::Vector3d& c) {
  std::array<Eigen::Vector3d, 3> p = {a, b, c};
  std::sort(p.begin(), p.end(), lexLess);
  const Eigen::Vector3d n = (p[1] - p[0]).cross(p[2] - p[0]);
  return Eigen::Vector4d(n.x(), n.y(), n.z(), -n.dot(p[0]));
}

HalfSpace facePlane(const Eigen::Vector3d& a, const Eigen::Vector3d& b, const Eigen::Vector3d& c,
                    const Eigen::Vector3d& inside) {
  const Eigen::Vector4d plane = canonicalPlane(a, b, c);
  if (plane.head<3>().squaredNorm() == 0.0) throw std::invalid_argument("facePlane: degenerate triangle");
  const HalfSpace h(plane);
  const double s = h.eval(inside);
  if (s == 0.0) throw std::invalid_argument("facePlane: the inside point lies on the plane");
  return s < 0.0 ? h : h.opposite();
}

HalfSpace BBQuadric::faceHalfSpace(int a) const {
  const int i = (a + 1) % 4, j = (a + 2) % 4, k = (a + 3) % 4;
  return facePlane(V[i], V[j], V[k], V[a]);
}

Primitive BBQuadric::toPrimitive(int material, int object, bool solid) const {
  Primitive p;
  p.quadric = toQuadric();
  for (int a = 0; a < 4; ++a) p.clip.push_back(faceHalfSpace(a));
  p.material = material;
  p.object = object;
  p.solid = solid;
  return p;
}

SharedFace findSharedFace(const Tetrahedron& first, const Tetrahedron& second) {
  SharedFace f;
  int n = 0;
  bool used_a[4] = {false, false, false, false}, used_b[4] = {false, false, false, false};
  for (int i = 0; i < 4; ++i)
    for (int j = 0; j < 4; ++j)
      if (!used_b[j] && first[i] == second[j]) {
        if (n == 3) throw std::invalid_argument("tetrahedra share more than three vertices");
        f.a[n] = i;
        f.b[n] = j;
        ++n;
        used_a[i] = used_b[j] = true;
        break;
      }
  if (n != 3) throw std::invalid_argument("tetrahedra do not share a face");
  for (int i = 0; i < 4; ++i) {
    if (!used_a[i]) f.free_a = i;
    if (!used_b[i]) f.free_b = i;
  }
  return f;
}

void joinG0(const BBQuadric& patch, BBQuadric& neighbour) {
  const SharedFace f = findSharedFace(patch.V, neighbour.V);
  for (int s = 0; s < 3; ++s)
    for (int t = 0; t < 3; ++t) neighbour.C(f.b[s], f.b[t]) = patch.C(f.a[s], f.a[t]);
}

void joinG1(const BBQuadric& patch, BBQuadric& neighbour) {
  joinG0(patch, neighbour);
  const SharedFace f = findSharedFace(patch.V, neighbour.V);
  const Eigen::Vector4d lambda = patch.barycentric(neighbour.V[f.free_b]);
  for (int s = 0; s < 3; ++s) {
    const double v = patch.C.row(f.a[s]).dot(lambda);
    neighbour.C(f.b[s], f.free_b) = v;
    neighbour.C(f.free_b, f.b[s]) = v;
  }
}

void mergeContinuity(FaceContinuity& into, const FaceContinuity& o) {
  into.max_value_diff = std::max(into.max_value_diff, o.max_value_diff);
  into.max_angle_face_deg = std::max(into.max_angle_face_deg, o.max_angle_face_deg);
  into.max_angle_surface_deg = std::max(into.max_angle_surface_deg, o.max_angle_surface_deg);
  into.samples += o.samples;
  into.surface_points += o.surface_points;
}

FaceContinuity measureFaceContinuity(const Quadric& q1, const Quadric& q2, const Eigen::Vector3d& a,
                                     const Eigen::Vector3d& b, const Eigen::Vector3d& c,
                                     int subdivisions, double min_gradient) {
  FaceContinuity r;
  const int n = std::max(1, subdivisions);
  auto at = [&](int i, int j) {
    const double u = double(i) / n, v = double(j) / n;
    return Eigen::Vector3d((1.0 - u - v) * a + u * b + v * c);
  };
  const double diameter = std::max({(b - a).norm(), (c - a).norm(), (c - b).norm()});
  // Scale: largest gradient of either quadric on the face grid.
  double gmax = 0.0;
  for (int i = 0; i <= n; ++i)
    for (int j = 0; i + j <= n; ++j)
      gmax = std::max({gmax, q1.gradient(at(i, j)).norm(), q2.gradient(at(i, j)).norm()});
  if (gmax == 0.0) gmax = 1.0;
  const double gmin = min_gradient * gmax;
  auto normalAngle = [&](const Eigen::Vector3d& p, double& worst) {
    const Eigen::Vector3d g1 = q1.gradient(p), g2 = q2.gradient(p);
    if (g1.norm() > gmin && g2.norm() > gmin) worst = std::max(worst, angleDeg(g1, g2));
  };
  for (int i = 0; i <= n; ++i)
    for (int j = 0; i + j <= n; ++j) {
      const Eigen::Vector3d p = at(i, j);
      r.max_value_diff = std::max(r.max_value_diff, std::abs(q1.eval(p) - q2.eval(p)) / (gmax * diameter));
      normalAngle(p, r.max_angle_face_deg);
      ++r.samples;
    }
  // Surface crossings of q1 along the grid's segments (three directions).
  auto segment = [&](Eigen::Vector3d p, Eigen::Vector3d q) {
    double fp = q1.eval(p), fq = q1.eval(q);
    if (fp == 0.0) {
      normalAngle(p, r.max_angle_surface_deg);
      ++r.surface_points;
      return;
    }
    if ((fp < 0.0) == (fq < 0.0) || fq == 0.0) return;
    for (int it = 0; it < 60; ++it) {
      const Eigen::Vector3d m = 0.5 * (p + q);
      const double fm = q1.eval(m);
      if ((fm < 0.0) == (fp < 0.0)) {
        p = m;
        fp = fm;
      } else {
        q = m;
        fq = fm;
      }
    }
    normalAngle(0.5 * (p + q), r.max_angle_surface_deg);
    ++r.surface_points;
  };
  for (int i = 0; i <= n; ++i)
    for (int j = 0; i + j <= n; ++j) {
      if (i + j < n) {
        segment(at(i, j), at(i + 1, j));
        segment(at(i, j), at(i, j + 1));
      }
      if (i >= 1) segment(at(i, j), at(i - 1, j + 1));
    }
  return r;
}

}  // namespace qacc
