#include "modeling/marching_tetrahedra.h"

#include <cmath>
#include <limits>
#include <unordered_map>

#include "modeling/algebraic_surface.h"
#include "modeling/kuhn_mesh.h"

namespace qacc {

TriangleSoup marchingTetrahedra(const Polynomial3& f, const Eigen::AlignedBox3d& box, int level) {
  const TetMesh m = kuhnMesh(box, level, level, level);
  std::vector<double> val(m.vertices.size());
  for (std::size_t i = 0; i < m.vertices.size(); ++i) val[i] = f.eval(m.vertices[i]);
  // A vertex counts as inside when f <= 0.
  auto in = [&](int v) { return val[std::size_t(v)] <= 0.0; };
  TriangleSoup out;
  std::unordered_map<std::uint64_t, int> edgeVertex;
  auto cut = [&](int a, int b) {
    if (a > b) std::swap(a, b);
    const std::uint64_t key = (std::uint64_t(std::uint32_t(a)) << 32) | std::uint32_t(b);
    auto it = edgeVertex.find(key);
    if (it != edgeVertex.end()) return it->second;
    Eigen::Vector3d lo = m.vertices[std::size_t(a)], hi = m.vertices[std::size_t(b)];
    double flo = val[std::size_t(a)];
    for (int k = 0; k < 60; ++k) {  // bisection keeps the bracket exactly
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
    const Eigen::Vector3d n = (pb - pa).cross(pc - pa);
    if (n.squaredNorm() == 0.0) return;
    if (n.dot(f.gradient((pa + pb + pc) / 3.0)) < 0) std::swap(b, c);
    out.triangles.push_back({a, b, c});
  };
  for (const auto& t : m.tets) {
    std::array<int, 4> inside{}, outside{};
    int ni = 0, no = 0;
    for (int v : t) {
      if (in(v))
        inside[std::size_t(ni++)] = v;
      else
        outside[std::size_t(no++)] = v;
    }
    if (ni == 0 || no == 0) continue;
    if (ni == 1 || no == 1) {
      const int apex = ni == 1 ? inside[0] : outside[0];
      const auto& others = ni == 1 ? outside : inside;
      emit(cut(apex, others[0]), cut(apex, others[1]), cut(apex, others[2]));
    } else {  // 2 and 2: a quadrilateral
      const int p = cut(inside[0], outside[0]), q = cut(inside[0], outside[1]), r = cut(inside[1], outside[1]),
                s = cut(inside[1], outside[0]);
      emit(p, q, r);
      emit(p, r, s);
    }
  }
  return out;
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
