// Crack-free shared boundaries (shared_boundaries.h): snapping and insertion of the
// boundary vertices of pieces that share a clip plane.
#include "modeling/tessellation/shared_boundaries.h"

#include <algorithm>
#include <array>
#include <cmath>
#include <cstdint>
#include <map>
#include <numeric>
#include <unordered_map>
#include <utility>

#include "modeling/tessellation/surface_clipping.h"  // lexLess, PointKey

namespace qacc::tess {

namespace {

using Key = std::array<double, 4>;

struct Edge {
  int prim;
  Vector3d a, b;
};
struct Side {
  std::vector<std::pair<int, int>> planes;  // (primitive, clip index)
  std::vector<Edge> edges;
  std::vector<std::pair<int, Vector3d>> vertices;  // (primitive, point), distinct per primitive
};
struct Group {
  Side side[2];
};

using EdgeKey = std::pair<Vector3d, Vector3d>;
struct EdgeKeyLess {
  bool operator()(const EdgeKey& a, const EdgeKey& b) const {
    if (a.first != b.first) return lexLess(a.first, b.first);
    return lexLess(a.second, b.second);
  }
};
EdgeKey edgeKey(const Vector3d& a, const Vector3d& b) { return lexLess(b, a) ? EdgeKey{b, a} : EdgeKey{a, b}; }
bool onPlane(const HalfSpace& h, const Vector3d& x) {
  return std::abs(h.eval(x)) <= 1e-9 * (h.p.head<3>().norm() * x.norm() + std::abs(h.p[3])) + 1e-300;
}

// Boundary edges of prims[i]'s surface triangles on plane h: the edges that one surface
// triangle of the piece uses (an edge two of them use is inside the piece, even with both
// ends on the plane).
void collectEdges(int i, const HalfSpace& h, const TriangleMesh3& mesh, std::size_t surface, Side& side) {
  std::map<std::pair<Vector3d, Vector3d>, int, EdgeKeyLess> uses;
  std::vector<std::pair<Vector3d, Vector3d>> onPlaneEdges;
  for (std::size_t t = 0; t < surface && t < mesh.triangles.size(); ++t) {
    const auto& tri = mesh.triangles[t];
    bool on[3];
    for (int k = 0; k < 3; ++k) on[k] = onPlane(h, mesh.positions[std::size_t(tri[k])]);
    for (int k = 0; k < 3; ++k) {
      if (!on[k] || !on[(k + 1) % 3]) continue;
      const Vector3d& a = mesh.positions[std::size_t(tri[k])];
      const Vector3d& b = mesh.positions[std::size_t(tri[(k + 1) % 3])];
      if (uses[edgeKey(a, b)]++ == 0) onPlaneEdges.push_back({a, b});
    }
  }
  std::map<Vector3d, bool, PointKey> seen;
  for (const auto& [a, b] : onPlaneEdges) {
    if (uses[edgeKey(a, b)] != 1) continue;
    side.edges.push_back({i, a, b});
    for (const Vector3d* p : {&a, &b})
      if (seen.emplace(*p, true).second) side.vertices.push_back({i, *p});
  }
}

// A uniform hash grid over points, for neighbour queries within one cell size.
struct PointGrid {
  double cell;
  std::unordered_map<std::uint64_t, std::vector<int>> cells;
  static std::uint64_t key(std::int64_t x, std::int64_t y, std::int64_t z) {
    return (std::uint64_t(x & 0x1FFFFF) << 42) | (std::uint64_t(y & 0x1FFFFF) << 21) | std::uint64_t(z & 0x1FFFFF);
  }
  Eigen::Matrix<std::int64_t, 3, 1> index(const Vector3d& p) const {
    return (p / cell).array().floor().cast<std::int64_t>();
  }
  void add(const Vector3d& p, int id) {
    const auto c = index(p);
    cells[key(c.x(), c.y(), c.z())].push_back(id);
  }
  template <typename F>
  void near(const Vector3d& p, F&& f) const {
    const auto c = index(p);
    for (std::int64_t dz = -1; dz <= 1; ++dz)
      for (std::int64_t dy = -1; dy <= 1; ++dy)
        for (std::int64_t dx = -1; dx <= 1; ++dx) {
          auto it = cells.find(key(c.x() + dx, c.y() + dy, c.z() + dz));
          if (it == cells.end()) continue;
          for (int id : it->second) f(id);
        }
  }
};

int findRoot(std::vector<int>& parent, int x) {
  while (parent[std::size_t(x)] != x) x = parent[std::size_t(x)] = parent[std::size_t(parent[std::size_t(x)])];
  return x;
}

using Insertions = std::map<EdgeKey, std::vector<Vector3d>, EdgeKeyLess>;

// Splits the triangles of `mesh` along the edges that received vertices (a fan from the
// opposite corner), surface triangles first then the others, as before.
void applyInsertions(const Insertions& ins, const Quadric& q, TriangleMesh3& mesh, std::size_t& surface) {
  TriangleMesh3 out;
  std::size_t outSurface = 0;
  struct Tri {
    Vector3d p[3], n[3];
  };
  for (std::size_t t = 0; t < mesh.triangles.size(); ++t) {
    std::vector<Tri> work(1);
    for (int k = 0; k < 3; ++k) {
      work[0].p[k] = mesh.positions[std::size_t(mesh.triangles[t][k])];
      work[0].n[k] = mesh.normals[std::size_t(mesh.triangles[t][k])];
    }
    const bool cap = t >= surface;
    while (!work.empty()) {
      const Tri tri = work.back();
      work.pop_back();
      int split = -1;
      const std::vector<Vector3d>* points = nullptr;
      for (int k = 0; k < 3 && split < 0; ++k) {
        auto it = ins.find(edgeKey(tri.p[k], tri.p[(k + 1) % 3]));
        if (it != ins.end() && !it->second.empty()) {
          split = k;
          points = &it->second;
        }
      }
      if (split < 0) {
        const int base = int(out.positions.size());
        for (int k = 0; k < 3; ++k) {
          out.positions.push_back(tri.p[k]);
          out.normals.push_back(tri.n[k]);
        }
        out.triangles.push_back({base, base + 1, base + 2});
        if (!cap) ++outSurface;
        continue;
      }
      // The edge p[s] → p[s+1] with its inserted points in order along it, fanned from p[s+2].
      const Vector3d a = tri.p[split], b = tri.p[(split + 1) % 3], c = tri.p[(split + 2) % 3];
      const Vector3d na = tri.n[split], nb = tri.n[(split + 1) % 3], nc = tri.n[(split + 2) % 3];
      std::vector<std::pair<double, Vector3d>> along;
      for (const Vector3d& x : *points) along.push_back({(x - a).dot(b - a), x});
      std::sort(along.begin(), along.end(), [](const auto& l, const auto& r) { return l.first < r.first; });
      const Vector3d mean = (na + nb + nc).normalized();
      Vector3d prev = a, prevN = na;
      for (std::size_t m = 0; m <= along.size(); ++m) {
        Vector3d next = b, nextN = nb;
        if (m < along.size()) {
          next = along[m].second;
          if (cap) {
            nextN = na;
          } else {
            const Vector3d g = q.gradient(next);
            nextN = g.norm() > 0 ? Vector3d(g.normalized()) : mean;
            if (nextN.dot(mean) < 0) nextN = -nextN;
          }
        }
        Tri sub;
        sub.p[0] = prev, sub.p[1] = next, sub.p[2] = c;
        sub.n[0] = prevN, sub.n[1] = nextN, sub.n[2] = nc;
        // Its edge prev → next is not an inserted-into edge any more; the other two may be.
        if (m == 0 || m == along.size()) {
          work.push_back(sub);
        } else {
          const int base = int(out.positions.size());
          for (int k = 0; k < 3; ++k) {
            out.positions.push_back(sub.p[k]);
            out.normals.push_back(sub.n[k]);
          }
          out.triangles.push_back({base, base + 1, base + 2});
          if (!cap) ++outSurface;
        }
        prev = next;
        prevN = nextN;
      }
    }
  }
  // Surface triangles first: the work list emits in order per triangle, and caps come after.
  mesh = std::move(out);
  surface = outSurface;
}

}  // namespace

StitchReport stitchSharedBoundaries(const std::vector<Primitive>& prims, const std::vector<TriangleMesh3*>& meshes,
                                    std::vector<std::size_t>& surfaceTriangles) {
  StitchReport rep;
  // 1. Planes shared by the two sides, per object: the key is the plane oriented so that its
  //    first non-zero coefficient is positive.
  std::map<std::pair<int, Key>, Group> groups;
  for (std::size_t i = 0; i < prims.size(); ++i) {
    if (!meshes[i] || prims[i].isPlanar()) continue;
    for (std::size_t k = 0; k < prims[i].clip.size(); ++k) {
      const Vector4d& p = prims[i].clip[k].p;
      const int s = HalfSpace::firstNonZeroNegative(p) ? 1 : 0;
      const Vector4d c = s ? Vector4d(-p) : p;
      groups[{prims[i].object, Key{c[0], c[1], c[2], c[3]}}].side[s].planes.push_back({int(i), int(k)});
    }
  }
  std::vector<Group*> shared;
  for (auto& g : groups)
    if (!g.second.side[0].planes.empty() && !g.second.side[1].planes.empty()) shared.push_back(&g.second);
  rep.shared_planes = shared.size();
  if (shared.empty()) return rep;

  auto collect = [&](Group& g) {
    for (Side& s : g.side) {
      s.edges.clear();
      s.vertices.clear();
      for (const auto& [i, k] : s.planes)
        collectEdges(i, prims[std::size_t(i)].clip[std::size_t(k)], *meshes[std::size_t(i)],
                     surfaceTriangles[std::size_t(i)], s);
    }
  };

  // 2. Snap: boundary vertices on shared planes of different pieces closer than a rounding
  //    tolerance (corners that each piece found by its own Newton steps, from planes
  //    computed from different vertex triples) become one position, that of the lowest
  //    primitive — over all shared planes at once, so that a vertex on several of them
  //    moves to one place.
  // Each group's edges are collected in parallel (a group reads the meshes and writes only its
  // own sides), then used in the groups' order.
  auto collectAll = [&] {
#pragma omp parallel for schedule(dynamic, 16)
    for (long g = 0; g < long(shared.size()); ++g) collect(*shared[std::size_t(g)]);
  };
  collectAll();
  std::vector<std::pair<int, Vector3d>> pts;
  for (Group* g : shared)
    for (const Side& sd : g->side) pts.insert(pts.end(), sd.vertices.begin(), sd.vertices.end());
  std::vector<std::map<Vector3d, Vector3d, PointKey>> moves(prims.size());
  if (!pts.empty()) {
    Eigen::AlignedBox3d box;
    for (const auto& v : pts) box.extend(v.second);
    const double tol = 1e-7 * box.sizes().norm() + 1e-12 * box.max().cwiseAbs().maxCoeff() + 1e-300;
    PointGrid grid{tol * 4, {}};
    for (std::size_t m = 0; m < pts.size(); ++m) grid.add(pts[m].second, int(m));
    std::vector<int> parent(pts.size());
    std::iota(parent.begin(), parent.end(), 0);
    for (std::size_t m = 0; m < pts.size(); ++m)
      grid.near(pts[m].second, [&](int o) {
        if (pts[std::size_t(o)].first != pts[m].first && (pts[std::size_t(o)].second - pts[m].second).norm() <= tol) {
          const int ra = findRoot(parent, int(m)), rb = findRoot(parent, o);
          if (ra != rb) parent[std::size_t(std::max(ra, rb))] = std::min(ra, rb);
        }
      });
    // The representative: the member of the lowest primitive (then the lowest position).
    std::vector<int> representative(pts.size(), -1);
    for (std::size_t m = 0; m < pts.size(); ++m) {
      int& best = representative[std::size_t(findRoot(parent, int(m)))];
      if (best < 0 || pts[m].first < pts[std::size_t(best)].first ||
          (pts[m].first == pts[std::size_t(best)].first && lexLess(pts[m].second, pts[std::size_t(best)].second)))
        best = int(m);
    }
    for (std::size_t m = 0; m < pts.size(); ++m) {
      const Vector3d& to = pts[std::size_t(representative[std::size_t(findRoot(parent, int(m)))])].second;
      if (to != pts[m].second && moves[std::size_t(pts[m].first)].emplace(pts[m].second, to).second) ++rep.snapped;
    }
  }
#pragma omp parallel for schedule(dynamic, 64)
  for (long li = 0; li < long(prims.size()); ++li) {
    const std::size_t i = std::size_t(li);
    if (moves[i].empty()) continue;
    TriangleMesh3& m = *meshes[i];
    for (Vector3d& p : m.positions) {
      auto it = moves[i].find(p);
      if (it != moves[i].end()) p = it->second;
    }
    // A triangle whose two corners snapped to one point is dropped: its two other edges are
    // now one, still used by the two neighbours that had them.
    std::size_t kept = 0, keptSurface = 0;
    for (std::size_t t = 0; t < m.triangles.size(); ++t) {
      const auto& tri = m.triangles[t];
      const Vector3d &a = m.positions[std::size_t(tri[0])], &b = m.positions[std::size_t(tri[1])],
                     &c = m.positions[std::size_t(tri[2])];
      if (a == b || b == c || a == c) continue;
      if (t < surfaceTriangles[i]) ++keptSurface;
      m.triangles[kept++] = tri;
    }
    m.triangles.resize(kept);
    surfaceTriangles[i] = keptSurface;
  }

  // 3. Insert each side's boundary vertices into the other side's boundary edges.
  std::vector<Insertions> inserts(prims.size());
  collectAll();
  for (Group* g : shared) {
    double longest = 0, scale = 1;
    for (const Side& s : g->side)
      for (const Edge& e : s.edges) {
        longest = std::max(longest, (e.b - e.a).norm());
        scale = std::max({scale, e.a.cwiseAbs().maxCoeff(), e.b.cwiseAbs().maxCoeff()});
      }
    if (!(longest > 0)) continue;
    for (int s = 0; s < 2; ++s) {
      const Side& into = g->side[s];
      const Side& from = g->side[1 - s];
      PointGrid grid{longest, {}};
      for (std::size_t e = 0; e < into.edges.size(); ++e) grid.add(0.5 * (into.edges[e].a + into.edges[e].b), int(e));
      for (const auto& vertex : from.vertices) {
        // Named copies, not a structured binding: the lambda below captures x (C++17).
        const int j = vertex.first;
        const Vector3d& x = vertex.second;
        const double ownGap = distanceToQuadric(prims[std::size_t(j)].quadric, x);
        int best = -1;
        double bestDist = 1e300;
        grid.near(x, [&](int e) {
          const Edge& ed = into.edges[std::size_t(e)];
          const Vector3d d = ed.b - ed.a;
          const double l2 = d.squaredNorm();
          if (!(l2 > 0)) return;
          const double t = (x - ed.a).dot(d) / l2;
          if (!(t > 1e-9 && t < 1 - 1e-9)) return;
          const double off = (x - (ed.a + t * d)).norm();
          if (off > 0.25 * std::sqrt(l2) || off >= bestDist) return;
          best = e;
          bestDist = off;
        });
        if (best < 0) continue;
        const Edge& ed = into.edges[std::size_t(best)];
        // Where the quadric pieces meet: x no farther from the other piece's surface than
        // from its own (its own distance is its chord error when it came from a linear cut).
        const double otherGap = distanceToQuadric(prims[std::size_t(ed.prim)].quadric, x);
        if (otherGap > 2 * ownGap + 1e-7 * scale) continue;
        std::vector<Vector3d>& list = inserts[std::size_t(ed.prim)][edgeKey(ed.a, ed.b)];
        if (std::find(list.begin(), list.end(), x) == list.end()) {
          list.push_back(x);
          ++rep.inserted;
        }
      }
    }
  }
#pragma omp parallel for schedule(dynamic, 64)
  for (long li = 0; li < long(prims.size()); ++li) {
    const std::size_t i = std::size_t(li);
    if (!inserts[i].empty())
      applyInsertions(inserts[i], prims[i].quadric.normalized(), *meshes[i], surfaceTriangles[i]);
  }
  return rep;
}

}  // namespace qacc::tess
