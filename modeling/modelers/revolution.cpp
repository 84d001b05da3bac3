#include "modeling/modelers/revolution.h"

#include <algorithm>
#include <array>
#include <cmath>
#include <stdexcept>

#include "modeling/geometry/half_space.h"
#include "modeling/geometry/natural_quadrics.h"

namespace qacc {

namespace {

// Null vector of a 3x4 matrix by signed 3x3 cofactors (the generalised cross product).
Eigen::Vector4d nullVector(const Eigen::Matrix<double, 3, 4>& m) {
  Eigen::Vector4d v;
  for (int j = 0; j < 4; ++j) {
    Eigen::Matrix3d minor;
    int c = 0;
    for (int k = 0; k < 4; ++k)
      if (k != j) minor.col(c++) = m.col(k);
    v[j] = ((j % 2) ? -1.0 : 1.0) * minor.determinant();
  }
  return v;
}

RevolutionProfile oriented(double A, double C, double Iz, double J) {
  if (!(std::abs(A) > 0)) throw std::invalid_argument("revolution: degenerate profile (no r² term)");
  RevolutionProfile p;
  const double s = A > 0 ? 1.0 : -1.0;
  p.A = s * A;
  p.C = s * C;
  p.Iz = s * Iz;
  p.J = s * J;
  return p;
}

std::string pointName(std::size_t i) { return "profile point " + std::to_string(i); }

// The largest r² of a piece on its slab: at an end or at the vertex of r²(z).
double largestRadiusSquared(const RevolutionPiece& pc) {
  double hi = std::max(pc.profile.radiusSquared(pc.z0), pc.profile.radiusSquared(pc.z1));
  if (pc.profile.C != 0) {
    const double zv = -pc.profile.Iz / (2 * pc.profile.C);
    if (zv > pc.z0 && zv < pc.z1) hi = std::max(hi, pc.profile.radiusSquared(zv));
  }
  return hi;
}

// The corners of a box that holds the piece (its slab by its largest radius, widened by a
// relative 1e-9 against rounding), placed by M.
std::array<Eigen::Vector3d, 8> pieceHull(const RevolutionPiece& pc, const Eigen::Matrix4d& M) {
  const double r = std::sqrt(std::max(0.0, largestRadiusSquared(pc))) * (1 + 1e-9);
  const double pad = 1e-9 * std::max(std::fabs(pc.z0), std::fabs(pc.z1));
  std::array<Eigen::Vector3d, 8> out;
  for (int k = 0; k < 8; ++k) {
    const Eigen::Vector4d x(k & 1 ? r : -r, k & 2 ? r : -r, k & 4 ? pc.z1 + pad : pc.z0 - pad, 1.0);
    out[std::size_t(k)] = (M * x).head<3>();
  }
  return out;
}

}  // namespace

Quadric RevolutionProfile::quadric() const {
  // (3.1) with A = B, C, and 2I = Iz.
  return Quadric::fromCoefficients(A, A, C, 0, 0, 0, 0, 0, 0.5 * Iz, J);
}

RevolutionProfile profileThroughThreePoints(const ProfilePoint& p1, const ProfilePoint& p2,
                                            const ProfilePoint& p3) {
  const double y1 = p1.r * p1.r, y2 = p2.r * p2.r, y3 = p3.r * p3.r;  // y_i²
  const double z1 = p1.z, z2 = p2.z, z3 = p3.z;
  // (4.6), written as in the thesis (y_i² abbreviated y_i here).
  const double A = z2 * z2 * z1 - z1 * z1 * z2 + z3 * z3 * z2 + z1 * z1 * z3 - z2 * z2 * z3 - z3 * z3 * z1;
  const double C = y1 * z2 + y2 * z3 + y3 * z1 - y3 * z2 - y1 * z3 - y2 * z1;
  const double I = y1 * z3 * z3 - y2 * z3 * z3 + y2 * z1 * z1 - y3 * z1 * z1 - y1 * z2 * z2 + y3 * z2 * z2;
  const double J = y1 * z2 * z2 * z3 - y3 * z2 * z2 * z1 - y1 * z3 * z3 * z2 + y2 * z3 * z3 * z1 -
                   y2 * z1 * z1 * z3 + y3 * z1 * z1 * z2;
  return oriented(A, C, I, J);
}

RevolutionProfile profileThroughTwoPointsWithNormal(const ProfilePoint& p1, const ProfilePoint& p2,
                                                    const Eigen::Vector2d& n1) {
  // Unknowns (A, C, Iz, J): f(p1) = 0, f(p2) = 0, normal(p1) x n1 = 0, i.e.
  // 2 A r1 n1.z - (2 C z1 + Iz) n1.r = 0.
  Eigen::Matrix<double, 3, 4> m;
  m.row(0) << p1.r * p1.r, p1.z * p1.z, p1.z, 1.0;
  m.row(1) << p2.r * p2.r, p2.z * p2.z, p2.z, 1.0;
  m.row(2) << 2 * p1.r * n1.y(), -2 * p1.z * n1.x(), -n1.x(), 0.0;
  const Eigen::Vector4d v = nullVector(m);
  return oriented(v[0], v[1], v[2], v[3]);
}

std::vector<RevolutionPiece> revolutionPieces(const std::vector<ProfilePoint>& profile, RevolutionJoin join) {
  const std::size_t m = profile.size();
  if (m < 3) throw std::invalid_argument("revolution: the profile needs at least 3 points");
  if (join == RevolutionJoin::G0 && m % 2 == 0)
    throw std::invalid_argument("revolution: a G0 profile needs an odd number of points (3 per quadric, shared ends)");
  for (std::size_t i = 0; i < m; ++i)
    if (!(profile[i].r >= 0)) throw std::invalid_argument("revolution: " + pointName(i) + " has a negative radius");
  const double dir = profile[1].z > profile[0].z ? 1.0 : -1.0;
  for (std::size_t i = 1; i < m; ++i)
    if (!(dir * (profile[i].z - profile[i - 1].z) > 0))
      throw std::invalid_argument("revolution: profile z must be strictly monotone (" + pointName(i) + ")");

  std::vector<RevolutionPiece> pieces;
  auto add = [&](const RevolutionProfile& p, double za, double zb) {
    RevolutionPiece piece;
    piece.profile = p;
    piece.z0 = std::min(za, zb);
    piece.z1 = std::max(za, zb);
    pieces.push_back(piece);
  };
  if (join == RevolutionJoin::G0) {
    for (std::size_t k = 0; k + 2 < m; k += 2)
      add(profileThroughThreePoints(profile[k], profile[k + 1], profile[k + 2]), profile[k].z, profile[k + 2].z);
  } else {
    // C1 quadratic spline of r² in z: piece k is r² = v_k + s_k (z - z_k) + a_k (z - z_k)²
    // with a_k = (v_k+1 - v_k - s_k h_k) / h_k² and s_k+1 = s_k + 2 a_k h_k. Everything is
    // affine in the start slope s_0, which is chosen to minimise Σ (a_k+1 - a_k)², the
    // jumps of (r²)'' at the joins: the least oscillating member of the family, and the
    // exact quadric when all points lie on one.
    const std::size_t n = m - 1;
    auto curvatures = [&](double s0) {
      std::vector<double> a(n);
      double s = s0;
      for (std::size_t k = 0; k < n; ++k) {
        const double h = profile[k + 1].z - profile[k].z;
        const double v0 = profile[k].r * profile[k].r, v1 = profile[k + 1].r * profile[k + 1].r;
        a[k] = (v1 - v0 - s * h) / (h * h);
        s += 2 * a[k] * h;
      }
      return a;
    };
    const std::vector<double> a0 = curvatures(0.0), a1 = curvatures(1.0);
    double num = 0, den = 0;
    for (std::size_t k = 0; k + 1 < n; ++k) {
      const double j0 = a0[k + 1] - a0[k], jd = (a1[k + 1] - a1[k]) - j0;
      num += j0 * jd;
      den += jd * jd;
    }
    double s = den > 0 ? -num / den : 0.0;
    for (std::size_t k = 0; k < n; ++k) {
      const double zk = profile[k].z, h = profile[k + 1].z - zk;
      const double v0 = profile[k].r * profile[k].r, v1 = profile[k + 1].r * profile[k + 1].r;
      const double a = (v1 - v0 - s * h) / (h * h);
      // r² = a z² + b z + c  ⇔  (4.3) with A = 1, C = -a, Iz = -b, J = -c.
      const double b = s - 2 * a * zk, c = v0 - s * zk + a * zk * zk;
      add(oriented(1.0, -a, -b, -c), zk, profile[k + 1].z);
      s += 2 * a * h;
    }
  }
  // Refuse pieces whose circle radius vanishes strictly inside the slab (a gap).
  double scale = 0;
  for (const auto& p : profile) scale = std::max(scale, p.r * p.r);
  for (std::size_t k = 0; k < pieces.size(); ++k) {
    const auto& pc = pieces[k];
    double lo = std::min(pc.profile.radiusSquared(pc.z0), pc.profile.radiusSquared(pc.z1));
    if (pc.profile.C != 0) {
      const double zv = -pc.profile.Iz / (2 * pc.profile.C);
      if (zv > pc.z0 && zv < pc.z1) lo = std::min(lo, pc.profile.radiusSquared(zv));
    }
    if (lo < -1e-9 * std::max(scale, 1e-300))
      throw std::invalid_argument("revolution: quadric " + std::to_string(k) +
                                  " has no real circle inside its slab (the profile folds through the axis); "
                                  "move its points");
  }
  return pieces;
}

std::vector<Primitive> revolutionPrimitives(const std::vector<ProfilePoint>& profile, RevolutionJoin join,
                                            const Eigen::Vector3d& origin, const Eigen::Vector3d& direction,
                                            const ViewVolume* view, ViewCullCount* count) {
  ViewCullCount local(view != nullptr);
  ViewCullCount& seen = count ? *count : local;
  if (!(direction.norm() > 0)) throw std::invalid_argument("revolution: zero axis direction");
  const std::vector<RevolutionPiece> pieces = revolutionPieces(profile, join);
  // One plane per slab boundary, keeping the side below it; the piece above uses opposite().
  // Pieces are in profile order, so consecutive pieces share z1/z0 exactly.
  std::vector<double> zs;
  for (const auto& p : pieces) {
    zs.push_back(p.z0);
    zs.push_back(p.z1);
  }
  std::sort(zs.begin(), zs.end());
  zs.erase(std::unique(zs.begin(), zs.end()), zs.end());
  std::vector<HalfSpace> below;
  for (double z : zs) below.emplace_back(Eigen::Vector4d(0, 0, 1, -z));
  auto planeAt = [&](double z) -> const HalfSpace& {
    return below[std::size_t(std::lower_bound(zs.begin(), zs.end(), z) - zs.begin())];
  };
  const Eigen::Matrix4d M = alignZ(origin, direction);
  std::vector<Primitive> out;
  for (const auto& pc : pieces) {
    if (view) {
      const std::array<Eigen::Vector3d, 8> hull = pieceHull(pc, M);
      if (!seen.keep(view->mayContain(hull.data(), hull.size()))) continue;
    }
    Primitive p;
    p.quadric = pc.profile.quadric();
    p.clip.push_back(planeAt(pc.z0).opposite());  // z >= z0
    p.clip.push_back(planeAt(pc.z1));             // z <= z1
    out.push_back(p.transformed(M));
  }
  return out;
}

std::vector<Primitive> buildRevolution(const JsonNode& o, ObjectContext& ctx) {
  const JsonNode prof = o.at("profile");
  std::vector<ProfilePoint> profile;
  for (std::size_t i = 0; i < prof.size(); ++i) {
    const auto v = prof[i].numbers(2);
    if (v[0] < 0) prof[i][0].fail("radius must be >= 0");
    profile.push_back({v[0], v[1]});
  }
  const std::string j = o.string("join", "G0");
  RevolutionJoin join;
  if (j == "G0") join = RevolutionJoin::G0;
  else if (j == "G1") join = RevolutionJoin::G1;
  else o.at("join").fail("expected \"G0\" or \"G1\"");
  Eigen::Vector3d origin = Eigen::Vector3d::Zero(), direction = Eigen::Vector3d::UnitZ();
  if (auto axis = o.get("axis")) {
    origin = axis->vec3("origin", origin);
    direction = axis->vec3("direction", direction);
    if (!(direction.norm() > 0)) axis->at("direction").fail("must be a non-zero vector");
    axis->finish();
  }
  try {
    ViewCullCount seen(ctx.view != nullptr);
    std::vector<Primitive> prims = revolutionPrimitives(profile, join, origin, direction, ctx.view, &seen);
    ctx.note = seen.note();
    return prims;
  } catch (const std::invalid_argument& e) {
    prof.fail(e.what());
  }
}

namespace {
// The scene object type this modeler provides (loader/object_registry.h).
[[maybe_unused]] const bool kRegistered = registerObjectTypes({
    {"revolution", buildRevolution},
});

}  // namespace

}  // namespace qacc
