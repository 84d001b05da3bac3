#include "modeling/algebraic/degree_reduction.h"

#include <algorithm>
#include <cmath>
#include <limits>
#include <unordered_map>

#include "modeling/modelers/bb_quadric.h"
#include "modeling/algebraic/bb_tetra.h"
#include "modeling/algebraic/bernstein_roots.h"
#include "modeling/algebraic/kuhn_mesh.h"
#include "modeling/support/parallel_errors.h"

namespace qacc {
namespace {

// The 6 edges of a tetrahedron as vertex-slot pairs.
constexpr int kEdges[6][2] = {{0, 1}, {0, 2}, {0, 3}, {1, 2}, {1, 3}, {2, 3}};

Tetrahedron tetOf(const TetMesh& m, std::size_t t) {
  Tetrahedron v;
  for (int a = 0; a < 4; ++a) v[std::size_t(a)] = m.vertices[std::size_t(m.tets[t][std::size_t(a)])];
  return v;
}

std::uint64_t edgeKey(int a, int b) {
  if (a > b) std::swap(a, b);
  return (std::uint64_t(std::uint32_t(a)) << 32) | std::uint32_t(b);
}

MultiIndex4 vertexIndex(int a) {
  MultiIndex4 m = {0, 0, 0, 0};
  m[std::size_t(a)] = 2;
  return m;
}
MultiIndex4 edgeIndex(int a, int b) {
  MultiIndex4 m = {0, 0, 0, 0};
  m[std::size_t(a)] = 1;
  m[std::size_t(b)] = 1;
  return m;
}

// Q scaled to unit Frobenius norm (0 stays 0).
Eigen::Matrix4d unitQ(const Quadric& q) {
  const double n = q.Q.norm();
  return n > 0 ? Eigen::Matrix4d(q.Q / n) : q.Q;
}

bool sameQuadric(const Eigen::Matrix4d& a, const Eigen::Matrix4d& b, bool up_to_sign) {
  const double tol = 1e-9;
  if ((a - b).cwiseAbs().maxCoeff() <= tol) return true;
  return up_to_sign && (a + b).cwiseAbs().maxCoeff() <= tol;
}

// Roots in [0, 1] of c0 + c1 s + c2 s² (stable form).
int quadraticRoots01(double c0, double c1, double c2, double r[2]) {
  int n = 0;
  const double scale = std::max({std::fabs(c0), std::fabs(c1), std::fabs(c2)});
  if (scale == 0) return 0;
  if (std::fabs(c2) <= 1e-14 * scale) {
    if (c1 != 0) {
      const double s = -c0 / c1;
      if (s >= 0 && s <= 1) r[n++] = s;
    }
    return n;
  }
  const double disc = c1 * c1 - 4 * c2 * c0;
  if (disc < 0) return 0;
  const double q = -0.5 * (c1 + std::copysign(std::sqrt(disc), c1));
  double s1 = q / c2, s2 = q != 0 ? c0 / q : s1;
  if (s1 > s2) std::swap(s1, s2);
  if (s1 >= 0 && s1 <= 1) r[n++] = s1;
  if (s2 >= 0 && s2 <= 1 && s2 != s1) r[n++] = s2;
  return n;
}

struct LevelModel {
  TetMesh mesh;
  std::vector<BBTetra> reduced;  // degree 2, with the shared vertex/edge coefficients
  std::vector<char> kept;
  std::vector<char> visible;     // the tetrahedron may meet the view volume (all 1 without one)
  int built = 0;                 // cells whose Bernstein form was computed
};

// Which tetrahedra may meet the view (every one without a view), and which must be built:
// the cells of every cube at most one cube away (Chebyshev) from a cube with a visible cell.
// A visible cell takes its shared vertex and edge coefficients from the first cell in mesh
// order that contains the vertex or edge, and smoothing averages the edges around its
// vertices: all of those cells lie in cubes that touch the visible cell's cube, so the
// visible cells' coefficients are exactly those of the whole model.
void viewCells(const TetMesh& m, const ViewVolume* view, std::vector<char>& visible, std::vector<char>& needed) {
  const std::size_t T = m.tets.size();
  visible.assign(T, 1);
  needed.assign(T, 1);
  if (!view) return;
  std::vector<char> cubeVisible(std::size_t(m.nx) * m.ny * m.nz, 0);
  for (std::size_t t = 0; t < T; ++t) {
    const Tetrahedron v = tetOf(m, t);
    visible[t] = view->mayContain(v.data(), v.size());
    if (visible[t]) cubeVisible[std::size_t(m.cube[t])] = 1;
  }
  std::vector<char> cubeNeeded(cubeVisible.size(), 0);
  for (int k = 0; k < m.nz; ++k)
    for (int j = 0; j < m.ny; ++j)
      for (int i = 0; i < m.nx; ++i) {
        if (!cubeVisible[std::size_t((k * m.ny + j) * m.nx + i)]) continue;
        for (int kk = std::max(0, k - 1); kk <= std::min(m.nz - 1, k + 1); ++kk)
          for (int jj = std::max(0, j - 1); jj <= std::min(m.ny - 1, j + 1); ++jj)
            for (int ii = std::max(0, i - 1); ii <= std::min(m.nx - 1, i + 1); ++ii)
              cubeNeeded[std::size_t((kk * m.ny + jj) * m.nx + ii)] = 1;
      }
  for (std::size_t t = 0; t < T; ++t) needed[t] = cubeNeeded[std::size_t(m.cube[t])];
}

LevelModel buildLevel(const Polynomial3& f, const Eigen::AlignedBox3d& box, int level,
                      const DegreeReductionOptions& o, const ViewVolume* view) {
  LevelModel L;
  L.mesh = kuhnMesh(box, level, level, level);
  const TetMesh& m = L.mesh;
  const std::size_t T = m.tets.size();
  std::vector<char> needed;
  viewCells(m, view, L.visible, needed);
  for (char c : needed) L.built += c;
  std::vector<int> sign(T, 0);
  std::vector<BBTetra> own(T);
  const int n = f.degree();
  ParallelErrors errors;
#pragma omp parallel for schedule(static)
  for (long long ti = 0; ti < (long long)T; ++ti) {
    errors.run([&] {
      const std::size_t t = std::size_t(ti);
      if (!needed[t]) return;
      BBTetra B = BBTetra::fromPolynomial(f, tetOf(m, t));
      while (B.degree() < 2) B = B.elevated();
      sign[t] = B.strictSign();
      own[t] = n > 2 ? B.reducedTo(2) : B;
    });
  }
  errors.rethrow();
  // Shared coefficients: a vertex or an edge takes the value computed by the first
  // tetrahedron (in mesh order) that contains it, so all cells around it agree exactly.
  const double unset = std::numeric_limits<double>::quiet_NaN();
  std::vector<double> vc(m.vertices.size(), unset);
  std::unordered_map<std::uint64_t, double> ec;
  ec.reserve(T * 2);
  for (std::size_t t = 0; t < T; ++t) {
    if (!needed[t]) continue;
    const auto& tv = m.tets[t];
    for (int a = 0; a < 4; ++a)
      if (std::isnan(vc[std::size_t(tv[std::size_t(a)])])) vc[std::size_t(tv[std::size_t(a)])] = own[t].coefficient(vertexIndex(a));
    for (const auto& e : kEdges) ec.emplace(edgeKey(tv[std::size_t(e[0])], tv[std::size_t(e[1])]), own[t].coefficient(edgeIndex(e[0], e[1])));
  }
  if (o.smooth) {
    // Interior vertices only (their star is complete and centrally symmetric in a Kuhn
    // mesh, so "mean of the surrounding coefficients" is the affine-consistent value).
    std::vector<double> sum(m.vertices.size(), 0.0);
    std::vector<int> cnt(m.vertices.size(), 0);
    for (const auto& kv : ec) {
      const int a = int(kv.first >> 32), b = int(kv.first & 0xffffffffu);
      sum[std::size_t(a)] += kv.second;
      sum[std::size_t(b)] += kv.second;
      ++cnt[std::size_t(a)];
      ++cnt[std::size_t(b)];
    }
    for (int k = 1; k < m.nz; ++k)
      for (int j = 1; j < m.ny; ++j)
        for (int i = 1; i < m.nx; ++i) {
          const std::size_t v = std::size_t(m.gridVertex(i, j, k));
          if (cnt[v] > 0) vc[v] = sum[v] / cnt[v];
        }
  }
  L.reduced.resize(T);
  L.kept.assign(T, 1);
  for (std::size_t t = 0; t < T; ++t) {
    if (!L.visible[t]) {
      L.kept[t] = 0;
      continue;
    }
    BBTetra A(2, tetOf(m, t));
    const auto& tv = m.tets[t];
    for (int a = 0; a < 4; ++a) A.setCoefficient(vertexIndex(a), vc[std::size_t(tv[std::size_t(a)])]);
    for (const auto& e : kEdges)
      A.setCoefficient(edgeIndex(e[0], e[1]), ec.at(edgeKey(tv[std::size_t(e[0])], tv[std::size_t(e[1])])));
    if (o.cull && sign[t] != 0 && A.strictSign() == sign[t]) L.kept[t] = 0;
    L.reduced[t] = std::move(A);
  }
  return L;
}

// Newton projection of p onto f = 0 along ∇f; returns the distance moved (inf if it fails).
double projectDistance(const Polynomial3& f, const Eigen::Vector3d& p0, double scale) {
  Eigen::Vector3d p = p0;
  for (int it = 0; it < 30; ++it) {
    const double v = f.eval(p);
    const Eigen::Vector3d g = f.gradient(p);
    const double g2 = g.squaredNorm();
    if (!(g2 > 0)) break;
    const Eigen::Vector3d step = v * g / g2;
    p -= step;
    if (step.norm() <= 1e-12 * scale) return (p - p0).norm();
  }
  const double v = f.eval(p);
  const Eigen::Vector3d g = f.gradient(p);
  return std::fabs(v) <= 1e-9 * std::max(1.0, g.norm() * scale) ? (p - p0).norm()
                                                                  : std::numeric_limits<double>::infinity();
}

GeometricError measureError(const Polynomial3& f, const LevelModel& L, double scale) {
  const TetMesh& m = L.mesh;
  double maxPS = 0, sumPS = 0, maxSP = 0, sumSP = 0;
  long long nPS = 0, nSP = 0;
  const long long T = (long long)m.tets.size();
  ParallelErrors errors;
#pragma omp parallel for schedule(dynamic, 64) reduction(max : maxPS, maxSP) reduction(+ : sumPS, sumSP, nPS, nSP)
  for (long long ti = 0; ti < T; ++ti) {
    errors.run([&] {
      const std::size_t t = std::size_t(ti);
      if (!L.kept[t]) return;
      const Tetrahedron v = tetOf(m, t);
      const Quadric q = L.reduced[t].toBBQuadric().toQuadric();
      std::vector<std::pair<Eigen::Vector3d, Eigen::Vector3d>> segs;
      for (const auto& e : kEdges) segs.emplace_back(v[std::size_t(e[0])], v[std::size_t(e[1])]);
      for (int e = 0; e < 3; ++e) {  // midpoints of opposite edges
        const auto& a = kEdges[e];
        const auto& b = kEdges[5 - e];
        segs.emplace_back(0.5 * (v[std::size_t(a[0])] + v[std::size_t(a[1])]), 0.5 * (v[std::size_t(b[0])] + v[std::size_t(b[1])]));
      }
      for (int a = 0; a < 4; ++a) {  // vertex to the opposite face's centroid
        Eigen::Vector3d c = Eigen::Vector3d::Zero();
        for (int b = 0; b < 4; ++b)
          if (b != a) c += v[std::size_t(b)] / 3.0;
        segs.emplace_back(v[std::size_t(a)], c);
      }
      for (const auto& s : segs) {
        const Eigen::Vector3d d = s.second - s.first;
        const Eigen::Vector4d A = s.first.homogeneous();
        const Eigen::Vector4d D(d.x(), d.y(), d.z(), 0.0);
        double r[2];
        const int nr = quadraticRoots01(A.dot(q.Q * A), 2 * D.dot(q.Q * A), D.dot(q.Q * D), r);
        for (int k = 0; k < nr; ++k) {
          const double dist = projectDistance(f, s.first + r[k] * d, scale);
          if (std::isfinite(dist)) {
            maxPS = std::max(maxPS, dist);
            sumPS += dist;
            ++nPS;
          }
        }
        for (double u : allBernsteinRoots(powerToBernstein(f.alongLine(s.first, d)))) {
          const Eigen::Vector3d p = s.first + u * d;
          const double g = q.gradient(p).norm();
          if (!(g > 0)) continue;
          const double dist = std::fabs(q.eval(p)) / g;
          maxSP = std::max(maxSP, dist);
          sumSP += dist;
          ++nSP;
        }
      }
    });
  }
  errors.rethrow();
  GeometricError e;
  e.max_piece_to_surface = maxPS;
  e.mean_piece_to_surface = nPS ? sumPS / double(nPS) : 0.0;
  e.max_surface_to_piece = maxSP;
  e.mean_surface_to_piece = nSP ? sumSP / double(nSP) : 0.0;
  e.samples = int(nPS + nSP);
  return e;
}

}  // namespace

DegreeReductionResult reduceAlgebraic(const Polynomial3& f, const Eigen::AlignedBox3d& box,
                                      const DegreeReductionOptions& o) {
  if (o.level < 1) throw std::invalid_argument("reduceAlgebraic: level must be >= 1");
  if (f.degree() > 16) throw std::invalid_argument("reduceAlgebraic: degree above 16 is not supported");
  const double scale = box.sizes().maxCoeff();
  int level = o.level;
  // The view culls at build time only when the level is fixed and cells are not merged
  // (DegreeReductionOptions::view); otherwise the whole model is built and culled below.
  const bool cullWhileBuilding = o.view && !o.merge && !(o.refine_error > 0);
  LevelModel L = buildLevel(f, box, level, o, cullWhileBuilding ? o.view : nullptr);
  GeometricError err = measureError(f, L, scale);
  while (o.refine_error > 0 && err.max() > o.refine_error && level * 2 <= o.max_level) {
    level *= 2;  // Bey 1 → 8 split of every Kuhn tetrahedron = the Kuhn mesh of half the spacing
    L = buildLevel(f, box, level, o, nullptr);
    err = measureError(f, L, scale);
  }
  if (o.view && !cullWhileBuilding && !o.merge) {
    std::vector<char> needed;
    viewCells(L.mesh, o.view, L.visible, needed);
    for (std::size_t t = 0; t < L.kept.size(); ++t) L.kept[t] = L.kept[t] && L.visible[t];
  }

  DegreeReductionResult R;
  R.level = level;
  R.cells = int(L.mesh.tets.size());
  R.built_cells = L.built;
  for (char v : L.visible) R.view_culled_cells += !v;
  R.error = err;
  const std::size_t T = L.mesh.tets.size();
  std::vector<Quadric> quad(T);
  std::vector<Eigen::Matrix4d> unit(T);
  for (std::size_t t = 0; t < T; ++t) {
    if (!L.kept[t] && !o.merge) continue;
    quad[t] = L.reduced[t].toBBQuadric().toQuadric();
    unit[t] = unitQ(quad[t]);
  }
  // Distinct quadrics among the kept pieces (up to scale and sign: the same surface).
  std::vector<Eigen::Matrix4d> distinct;
  for (std::size_t t = 0; t < T; ++t) {
    if (!L.kept[t]) continue;
    ++R.kept_cells;
    bool found = false;
    for (const auto& d : distinct)
      if (sameQuadric(unit[t], d, true)) {
        found = true;
        break;
      }
    if (!found) distinct.push_back(unit[t]);
  }
  R.distinct_quadrics = int(distinct.size());

  std::vector<char> done(T, 0);
  if (o.merge) {
    // A cube merges when its 6 cells carry the same polynomial (up to a positive factor):
    // the culled ones are then empty for that quadric too. Boxes of such cubes grow along
    // x, then y, then z.
    const TetMesh& m = L.mesh;
    const int nc = m.nx * m.ny * m.nz;
    std::vector<char> uniform(std::size_t(nc), 0), anyKept(std::size_t(nc), 0), used(std::size_t(nc), 0);
    for (int c = 0; c < nc; ++c) {
      bool same = true;
      for (int s = 0; s < 6; ++s) {
        const std::size_t t = std::size_t(c * 6 + s);
        same = same && sameQuadric(unit[t], unit[std::size_t(c * 6)], false);
        if (L.kept[t]) anyKept[std::size_t(c)] = 1;
      }
      uniform[std::size_t(c)] = same;  // culled cells are empty for this quadric too
    }
    auto cubeId = [&](int i, int j, int k) { return (k * m.ny + j) * m.nx + i; };
    auto fits = [&](int c, int seed) {
      return uniform[std::size_t(c)] && !used[std::size_t(c)] &&
             sameQuadric(unit[std::size_t(c * 6)], unit[std::size_t(seed * 6)], false);
    };
    for (int k = 0; k < m.nz; ++k)
      for (int j = 0; j < m.ny; ++j)
        for (int i = 0; i < m.nx; ++i) {
          const int seed = cubeId(i, j, k);
          if (!uniform[std::size_t(seed)] || used[std::size_t(seed)]) continue;
          int i1 = i + 1, j1 = j + 1, k1 = k + 1;
          while (i1 < m.nx && fits(cubeId(i1, j, k), seed)) ++i1;
          auto rowOk = [&](int jj, int kk) {
            for (int ii = i; ii < i1; ++ii)
              if (!fits(cubeId(ii, jj, kk), seed)) return false;
            return true;
          };
          while (j1 < m.ny && rowOk(j1, k)) ++j1;
          auto layerOk = [&](int kk) {
            for (int jj = j; jj < j1; ++jj)
              if (!rowOk(jj, kk)) return false;
            return true;
          };
          while (k1 < m.nz && layerOk(k1)) ++k1;
          int cells = 0;
          bool kept = false;
          for (int kk = k; kk < k1; ++kk)
            for (int jj = j; jj < j1; ++jj)
              for (int ii = i; ii < i1; ++ii) {
                const int c = cubeId(ii, jj, kk);
                used[std::size_t(c)] = 1;
                kept = kept || anyKept[std::size_t(c)];
                for (int s = 0; s < 6; ++s) done[std::size_t(c * 6 + s)] = 1;
                cells += 6;
              }
          if (!kept) continue;  // the whole box is empty for its quadric
          const Eigen::Vector3d lo = m.vertices[std::size_t(m.gridVertex(i, j, k))];
          const Eigen::Vector3d hi = m.vertices[std::size_t(m.gridVertex(i1, j1, k1))];
          const Eigen::Vector3d mid = 0.5 * (lo + hi);
          Primitive p;
          p.quadric = quad[std::size_t(seed * 6)];
          for (int a = 0; a < 3; ++a)
            for (int side = 0; side < 2; ++side) {
              const double c = side ? hi[a] : lo[a];
              const int b = (a + 1) % 3, d = (a + 2) % 3;
              Eigen::Vector3d p0, p1, p2;
              p0[a] = p1[a] = p2[a] = c;
              p0[b] = lo[b]; p0[d] = lo[d];
              p1[b] = hi[b]; p1[d] = lo[d];
              p2[b] = lo[b]; p2[d] = hi[d];
              p.clip.push_back(facePlane(p0, p1, p2, mid));
            }
          p.material = o.material;
          p.object = o.object;
          R.primitives.push_back(std::move(p));
          if (cells > 1) ++R.merged_groups;
        }
  }
  for (std::size_t t = 0; t < T; ++t) {
    if (!L.kept[t] || done[t]) continue;
    R.primitives.push_back(L.reduced[t].toBBQuadric().toPrimitive(o.material, o.object, false));
  }
  return R;
}

}  // namespace qacc
