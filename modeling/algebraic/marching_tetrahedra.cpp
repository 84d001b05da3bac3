#include "modeling/algebraic/marching_tetrahedra.h"

#include <algorithm>
#include <cmath>
#include <limits>
#include <stdexcept>
#include <unordered_map>

#include "modeling/algebraic/algebraic_surface.h"
#include "modeling/algebraic/kuhn_mesh.h"

namespace qacc {

void marchKuhnGrid(const Eigen::Vector3i& cubes, const std::vector<double>& samples, const KuhnCrossings& out) {
  const std::int64_t nx = cubes.x() + 1, ny = cubes.y() + 1;
  auto index = [nx, ny](const Eigen::Vector3i& c) { return (std::int64_t(c.z()) * ny + c.y()) * nx + c.x(); };
  auto in = [&](const Eigen::Vector3i& c) { return samples[std::size_t(index(c))] <= 0.0; };
  auto edge = [&](const Eigen::Vector3i& u, const Eigen::Vector3i& v) {
    KuhnEdge e{u, v, index(u), index(v)};
    if (e.ia > e.ib) {
      std::swap(e.a, e.b);
      std::swap(e.ia, e.ib);
    }
    return e;
  };
  for (int k = 0; k < cubes.z(); ++k)
    for (int j = 0; j < cubes.y(); ++j)
      for (int i = 0; i < cubes.x(); ++i) {
        int nin = 0;  // a cube with all 8 corners on one side has no crossing tetrahedron
        for (int c = 0; c < 8; ++c) nin += in({i + (c & 1), j + ((c >> 1) & 1), k + ((c >> 2) & 1)});
        if (nin == 0 || nin == 8) continue;
        for (const auto& t : kuhnCubeTets(i, j, k)) {
          std::array<Eigen::Vector3i, 4> inside, outside;
          int ni = 0, no = 0;
          for (const auto& v : t) {
            if (in(v))
              inside[std::size_t(ni++)] = v;
            else
              outside[std::size_t(no++)] = v;
          }
          if (ni == 0 || no == 0) continue;
          if (ni == 1 || no == 1) {
            const Eigen::Vector3i apex = ni == 1 ? inside[0] : outside[0];
            const auto& others = ni == 1 ? outside : inside;
            out.triangle(edge(apex, others[0]), edge(apex, others[1]), edge(apex, others[2]));
          } else {  // 2 and 2: a quadrilateral
            out.quad(edge(inside[0], outside[0]), edge(inside[0], outside[1]), edge(inside[1], outside[1]),
                     edge(inside[1], outside[0]));
          }
        }
      }
}

TriangleSoup marchingTetrahedra(const Polynomial3& f, const Eigen::AlignedBox3d& box, int level) {
  if (level < 1) throw std::invalid_argument("marchingTetrahedra: at least one cube per axis");
  if (box.isEmpty() || !(box.sizes().array() > 0.0).all()) throw std::invalid_argument("marchingTetrahedra: empty box");
  // The Kuhn mesh of kuhn_mesh.h, walked cube by cube (only the grid values are stored).
  const Eigen::Vector3i n(level, level, level);
  const int N = level + 1;
  std::vector<double> val(std::size_t(N) * std::size_t(N) * std::size_t(N));
#pragma omp parallel for schedule(static)
  for (int k = 0; k < N; ++k)
    for (int j = 0; j < N; ++j)
      for (int i = 0; i < N; ++i)
        val[(std::size_t(k) * std::size_t(N) + std::size_t(j)) * std::size_t(N) + std::size_t(i)] =
            f.eval(kuhnGridPoint(box, n, i, j, k));
  TriangleSoup out;
  std::unordered_map<std::uint64_t, int> edgeVertex;
  auto cut = [&](const KuhnEdge& e) {
    const std::uint64_t key = (std::uint64_t(std::uint32_t(e.ia)) << 32) | std::uint32_t(e.ib);
    auto it = edgeVertex.find(key);
    if (it != edgeVertex.end()) return it->second;
    Eigen::Vector3d lo = kuhnGridPoint(box, n, e.a.x(), e.a.y(), e.a.z()), hi = kuhnGridPoint(box, n, e.b.x(), e.b.y(), e.b.z());
    double flo = val[std::size_t(e.ia)];
    for (int s = 0; s < 60; ++s) {  // bisection keeps the bracket exactly
      const Eigen::Vector3d mid = 0.5 * (lo + hi);
      const double fm = f.eval(mid);
      if ((fm <= 0.0) == (flo <= 0.0)) {
        lo = mid;
        flo = fm;
      } else {
        hi = mid;
      }
    }
    out.vertices.push_back(0.5 * (lo + hi));
    const int id = int(out.vertices.size()) - 1;
    edgeVertex.emplace(key, id);
    return id;
  };
  auto emit = [&](int a, int b, int c) {
    const Eigen::Vector3d& pa = out.vertices[std::size_t(a)];
    const Eigen::Vector3d& pb = out.vertices[std::size_t(b)];
    const Eigen::Vector3d& pc = out.vertices[std::size_t(c)];
    const Eigen::Vector3d nrm = (pb - pa).cross(pc - pa);
    if (nrm.squaredNorm() == 0.0) return;
    if (nrm.dot(f.gradient((pa + pb + pc) / 3.0)) < 0) std::swap(b, c);
    out.triangles.push_back({a, b, c});
  };
  KuhnCrossings crossings;
  crossings.triangle = [&](const KuhnEdge& e0, const KuhnEdge& e1, const KuhnEdge& e2) { emit(cut(e0), cut(e1), cut(e2)); };
  crossings.quad = [&](const KuhnEdge& e0, const KuhnEdge& e1, const KuhnEdge& e2, const KuhnEdge& e3) {
    const int p = cut(e0), q = cut(e1), r = cut(e2), s = cut(e3);
    emit(p, q, r);
    emit(p, r, s);
  };
  marchKuhnGrid(n, val, crossings);
  return out;
}

TriangleSoup marchingTetrahedraOfSize(const Polynomial3& f, const Eigen::AlignedBox3d& box, std::size_t triangles,
                                      int* levelOut) {
  const double target = double(std::max<std::size_t>(triangles, 1));
  // Closeness of a mesh's count to the target (log ratio; an empty mesh is the worst).
  auto miss = [&](const TriangleSoup& m) {
    return m.triangles.empty() ? HUGE_VAL : std::abs(std::log(double(m.triangles.size()) / target));
  };
  const int pilot = 16;
  int level = pilot;
  TriangleSoup mesh = marchingTetrahedra(f, box, level);
  auto consider = [&](int n) {
    TriangleSoup m = marchingTetrahedra(f, box, n);
    if (miss(m) < miss(mesh)) {
      mesh = std::move(m);
      level = n;
    }
  };
  const double predicted = mesh.triangles.empty() ? 0.0 : pilot * std::sqrt(target / double(mesh.triangles.size()));
  if (mesh.triangles.empty() || predicted < pilot) {
    // Grids up to the pilot's are cheap, and coarse grids that do not resolve the surface
    // stray from the square law: try them all (and 64 for a surface the pilot misses).
    for (int n = 1; n < pilot; ++n) consider(n);
    if (mesh.triangles.empty()) consider(64);
  } else {
    // The count grows as the square of the grid once the grid resolves the surface; one
    // more correction when the prediction is more than 20 % off.
    int n = int(std::min(std::lround(predicted), long(kMaxMarchingLevel)));
    for (int step = 0; step < 2 && n != level && miss(mesh) > std::log(1.2); ++step) {
      consider(n);
      n = int(std::clamp(std::lround(level * std::sqrt(target / double(mesh.triangles.size()))), 1L,
                         long(kMaxMarchingLevel)));
    }
  }
  if (levelOut) *levelOut = level;
  return mesh;
}

namespace {

// Distance from p to the triangle (a, b, c) (Ericson, Real-Time Collision Detection 5.1.5).
double pointTriangleDistance(const Eigen::Vector3d& p, const Eigen::Vector3d& a, const Eigen::Vector3d& b,
                             const Eigen::Vector3d& c) {
  const Eigen::Vector3d ab = b - a, ac = c - a, ap = p - a;
  const double d1 = ab.dot(ap), d2 = ac.dot(ap);
  if (d1 <= 0 && d2 <= 0) return (p - a).norm();
  const Eigen::Vector3d bp = p - b;
  const double d3 = ab.dot(bp), d4 = ac.dot(bp);
  if (d3 >= 0 && d4 <= d3) return (p - b).norm();
  const double vc = d1 * d4 - d3 * d2;
  if (vc <= 0 && d1 >= 0 && d3 <= 0) return (p - (a + ab * (d1 / (d1 - d3)))).norm();
  const Eigen::Vector3d cp = p - c;
  const double d5 = ab.dot(cp), d6 = ac.dot(cp);
  if (d6 >= 0 && d5 <= d6) return (p - c).norm();
  const double vb = d5 * d2 - d1 * d6;
  if (vb <= 0 && d2 >= 0 && d6 <= 0) return (p - (a + ac * (d2 / (d2 - d6)))).norm();
  const double va = d3 * d6 - d5 * d4;
  if (va <= 0 && (d4 - d3) >= 0 && (d5 - d6) >= 0)
    return (p - (b + (c - b) * ((d4 - d3) / ((d4 - d3) + (d5 - d6))))).norm();
  const double denom = 1.0 / (va + vb + vc);
  return (p - (a + ab * (vb * denom) + ac * (vc * denom))).norm();
}

}  // namespace

FacetError facetError(const Polynomial3& f, const TriangleSoup& mesh, const Eigen::AlignedBox3d& box) {
  const double scale = box.sizes().maxCoeff();
  double mx = 0, sum = 0;
  long long n = 0;
  const long long T = (long long)mesh.triangles.size();
#pragma omp parallel for schedule(static) reduction(max : mx) reduction(+ : sum, n)
  for (long long i = 0; i < T; ++i) {
    const auto& t = mesh.triangles[std::size_t(i)];
    const Eigen::Vector3d a = mesh.vertices[std::size_t(t[0])], b = mesh.vertices[std::size_t(t[1])],
                          c = mesh.vertices[std::size_t(t[2])];
    const Eigen::Vector3d samples[4] = {(a + b + c) / 3.0, 0.5 * (a + b), 0.5 * (b + c), 0.5 * (c + a)};
    for (const auto& p0 : samples) {
      Eigen::Vector3d p = p0;
      bool ok = false;
      for (int it = 0; it < 30; ++it) {
        const Eigen::Vector3d g = f.gradient(p);
        if (!(g.squaredNorm() > 0)) break;
        const Eigen::Vector3d step = f.eval(p) * g / g.squaredNorm();
        p -= step;
        if (step.norm() <= 1e-12 * scale) {
          ok = true;
          break;
        }
      }
      if (!ok) continue;
      const double d = (p - p0).norm();
      mx = std::max(mx, d);
      sum += d;
      ++n;
    }
  }
  // Surface → triangles, with triangles bucketed on a 16^3 grid.
  const int B = 16;
  const Eigen::Vector3d cell = box.sizes() / B;
  auto bucketOf = [&](const Eigen::Vector3d& p, int axis) {
    return std::min(B - 1, std::max(0, int(std::floor((p[axis] - box.min()[axis]) / cell[axis]))));
  };
  std::vector<std::vector<int>> buckets(std::size_t(B * B * B));
  for (std::size_t i = 0; i < mesh.triangles.size(); ++i) {
    Eigen::AlignedBox3d tb;
    for (int v : mesh.triangles[i]) tb.extend(mesh.vertices[std::size_t(v)]);
    for (int z = bucketOf(tb.min(), 2); z <= bucketOf(tb.max(), 2); ++z)
      for (int y = bucketOf(tb.min(), 1); y <= bucketOf(tb.max(), 1); ++y)
        for (int x = bucketOf(tb.min(), 0); x <= bucketOf(tb.max(), 0); ++x)
          buckets[std::size_t((z * B + y) * B + x)].push_back(int(i));
  }
  std::vector<Eigen::Vector3d> surface;
  const int G = 40;
  const AlgebraicSurface truth(f, box);
  for (int axis = 0; axis < 3; ++axis)
    for (int i = 0; i < G; ++i)
      for (int j = 0; j < G; ++j) {
        const int u = (axis + 1) % 3, v = (axis + 2) % 3;
        Eigen::Vector3d p0, p1;
        p0[u] = p1[u] = box.min()[u] + box.sizes()[u] * (i + 0.5) / G;
        p0[v] = p1[v] = box.min()[v] + box.sizes()[v] * (j + 0.5) / G;
        p0[axis] = box.min()[axis];
        p1[axis] = box.max()[axis];
        for (double t : truth.allRoots(p0, p1)) surface.push_back(p0 + t * (p1 - p0));
      }
  const long long S = (long long)surface.size();
#pragma omp parallel for schedule(dynamic, 64) reduction(max : mx) reduction(+ : sum, n)
  for (long long k = 0; k < S; ++k) {
    const Eigen::Vector3d& p = surface[std::size_t(k)];
    double best = std::numeric_limits<double>::infinity();
    const int bx = bucketOf(p, 0), by = bucketOf(p, 1), bz = bucketOf(p, 2);
    for (int z = std::max(0, bz - 1); z <= std::min(B - 1, bz + 1); ++z)
      for (int y = std::max(0, by - 1); y <= std::min(B - 1, by + 1); ++y)
        for (int x = std::max(0, bx - 1); x <= std::min(B - 1, bx + 1); ++x)
          for (int ti : buckets[std::size_t((z * B + y) * B + x)]) {
            const auto& t = mesh.triangles[std::size_t(ti)];
            best = std::min(best, pointTriangleDistance(p, mesh.vertices[std::size_t(t[0])],
                                                        mesh.vertices[std::size_t(t[1])], mesh.vertices[std::size_t(t[2])]));
          }
    mx = std::max(mx, best);
    if (std::isfinite(best)) sum += best;
    ++n;
  }
  FacetError e;
  e.max = mx;
  e.mean = n ? sum / double(n) : 0.0;
  e.samples = int(n);
  return e;
}

}  // namespace qacc
