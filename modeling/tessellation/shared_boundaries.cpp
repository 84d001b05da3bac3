// Crack-free shared boundaries (shared_boundaries.h): one polyline per pair of pieces on a
// shared plane, each piece's strip zipped onto its polylines.
#include "modeling/tessellation/shared_boundaries.h"

#include <algorithm>
#include <array>
#include <cmath>
#include <cstdint>
#include <map>
#include <numeric>
#include <optional>
#include <unordered_map>
#include <utility>

#include "modeling/tessellation/boundary_strip.h"
#include "modeling/tessellation/shared_polyline.h"
#include "modeling/tessellation/surface_clipping.h"  // lexLess

namespace qacc::tess {

namespace {

using Key = std::array<double, 4>;

struct Group {
  std::vector<std::pair<int, int>> side[2];  // (primitive, clip index)
  bool refused = false;
};

struct Pair {
  Group* group;
  int lo, klo, hi, khi;  // primitives (lo: the canonical one, on side 0) and their clip indices
  std::vector<HalfSpace> face;
  Vector3d end[2];
  std::vector<Vector3d> polyline;
};

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

// Ends closer than a rounding tolerance become one point, the least of them.
void snapEnds(std::vector<Pair>& pairs) {
  std::vector<Vector3d*> pts;
  for (Pair& p : pairs)
    for (Vector3d& e : p.end) pts.push_back(&e);
  if (pts.empty()) return;
  Eigen::AlignedBox3d box;
  for (const Vector3d* v : pts) box.extend(*v);
  const double tol = 1e-7 * box.sizes().norm() + 1e-12 * box.max().cwiseAbs().maxCoeff() + 1e-300;
  PointGrid grid{tol * 4, {}};
  for (std::size_t m = 0; m < pts.size(); ++m) grid.add(*pts[m], int(m));
  std::vector<int> parent(pts.size());
  std::iota(parent.begin(), parent.end(), 0);
  for (std::size_t m = 0; m < pts.size(); ++m)
    grid.near(*pts[m], [&](int o) {
      if ((*pts[std::size_t(o)] - *pts[m]).norm() <= tol) {
        const int ra = findRoot(parent, int(m)), rb = findRoot(parent, o);
        if (ra != rb) parent[std::size_t(std::max(ra, rb))] = std::min(ra, rb);
      }
    });
  std::vector<Vector3d> least(pts.size());
  std::vector<char> set(pts.size(), 0);
  for (std::size_t m = 0; m < pts.size(); ++m) {
    const std::size_t r = std::size_t(findRoot(parent, int(m)));
    if (!set[r] || lexLess(*pts[m], least[r])) least[r] = *pts[m];
    set[r] = 1;
  }
  for (std::size_t m = 0; m < pts.size(); ++m) *pts[m] = least[std::size_t(findRoot(parent, int(m)))];
}

// Two samplings of one arc: the same ends, and every vertex of each within 1 % of the chord
// of the other (two different arcs between the same ends lie about a chord apart).
bool sameArc(const std::vector<Vector3d>& a, const std::vector<Vector3d>& b) {
  if (a == b) return true;
  if (a.empty() || b.empty() || a.front() != b.front() || a.back() != b.back()) return false;
  const double within = 1e-2 * (a.back() - a.front()).norm();
  const std::vector<std::vector<Vector3d>> la{a}, lb{b};
  for (const Vector3d& x : a)
    if (distanceToSegments(x, lb) > within) return false;
  for (const Vector3d& x : b)
    if (distanceToSegments(x, la) > within) return false;
  return true;
}

}  // namespace

StitchReport stitchSharedBoundaries(const std::vector<Primitive>& prims, const std::vector<TriangleMesh3*>& meshes,
                                    std::vector<std::size_t>& surfaceTriangles, const SharedBoundarySampling& sampling) {
  StitchReport rep;
  // Planes shared by the two sides, per object: the key is the plane oriented so that its
  // first non-zero coefficient is positive.
  std::map<std::pair<int, Key>, Group> groups;
  for (std::size_t i = 0; i < prims.size(); ++i) {
    if (!meshes[i] || prims[i].isPlanar() || prims[i].solid) continue;
    for (std::size_t k = 0; k < prims[i].clip.size(); ++k) {
      const Vector4d& p = prims[i].clip[k].p;
      const int s = HalfSpace::firstNonZeroNegative(p) ? 1 : 0;
      const Vector4d c = s ? Vector4d(-p) : p;
      groups[{prims[i].object, Key{c[0], c[1], c[2], c[3]}}].side[s].push_back({int(i), int(k)});
    }
  }
  std::vector<Pair> pairs;
  for (auto& [key, g] : groups) {
    if (g.side[0].empty() || g.side[1].empty()) continue;
    ++rep.shared_planes;
    for (const auto& a : g.side[0])
      for (const auto& b : g.side[1]) {
        Pair p;
        p.group = &g;
        // The canonical piece: the one on side 0, whatever the primitives' order (view culling
        // may number them differently).
        p.lo = a.first;
        p.klo = a.second;
        p.hi = b.first;
        p.khi = b.second;
        for (const auto& [i, k] : {std::pair{p.lo, p.klo}, std::pair{p.hi, p.khi}}) {
          const auto& clip = prims[std::size_t(i)].clip;
          for (std::size_t m = 0; m < clip.size(); ++m)
            if (int(m) != k) p.face.push_back(clip[m]);
        }
        pairs.push_back(std::move(p));
      }
  }
  // 1. The arcs of each pair's curve on the common face (none: the faces do not meet there).
  std::vector<char> keep(pairs.size(), 0);
  std::vector<std::vector<Vector3d>> arcs(pairs.size());
#pragma omp parallel for schedule(dynamic, 16)
  for (long lp = 0; lp < long(pairs.size()); ++lp) {
    Pair& p = pairs[std::size_t(lp)];
    const Primitive& lo = prims[std::size_t(p.lo)];
    auto ends = sharedCurveEnds(lo.quadric.normalized(), lo.clip[std::size_t(p.klo)], p.face);
    keep[std::size_t(lp)] = !ends.empty();
    arcs[std::size_t(lp)] = std::move(ends);
  }
  {
    // One entry per arc, its ends in lexicographic order.
    std::vector<Pair> kept;
    for (std::size_t m = 0; m < pairs.size(); ++m)
      for (std::size_t a = 0; keep[m] == 1 && a + 1 < arcs[m].size(); a += 2) {
        Pair p = pairs[m];
        const bool swap = lexLess(arcs[m][a + 1], arcs[m][a]);
        p.end[0] = arcs[m][swap ? a + 1 : a];
        p.end[1] = arcs[m][swap ? a : a + 1];
        kept.push_back(std::move(p));
      }
    pairs = std::move(kept);
  }
  // 2. Corners common to all the pairs that end there.
  snapEnds(pairs);
  // 3. Each curve sampled once.
  std::vector<char> sampled(pairs.size(), 0);
#pragma omp parallel for schedule(dynamic, 16)
  for (long lp = 0; lp < long(pairs.size()); ++lp) {
    Pair& p = pairs[std::size_t(lp)];
    if (p.end[0] == p.end[1]) continue;
    const Primitive& lo = prims[std::size_t(p.lo)];
    PolylineTolerance tol;
    if (sampling.view) {
      tol.view = sampling.view;
      tol.pixels = sampling.pixels;
    } else {
      const double a = sampling.chordError[std::size_t(p.lo)], b = sampling.chordError[std::size_t(p.hi)];
      tol.world = a > 0 && b > 0 ? std::min(a, b) : std::max(a, b);
      if (!(tol.world > 0)) tol.world = 1e-3 * (p.end[1] - p.end[0]).norm();
    }
    auto line = sampleSharedCurve(lo.quadric.normalized(), lo.clip[std::size_t(p.klo)], p.face, p.end[0], p.end[1], tol);
    if (line) {
      p.polyline = std::move(*line);
      sampled[std::size_t(lp)] = 1;
    } else {
      sampled[std::size_t(lp)] = 2;
    }
  }
  for (std::size_t m = 0; m < pairs.size(); ++m)
    if (sampled[m] == 2) pairs[m].group->refused = true;
  // 4. Per piece: its planes with a polyline, and the polylines on them.
  std::vector<std::vector<HalfSpace>> planes(prims.size());
  std::vector<std::vector<std::vector<Vector3d>>> lines(prims.size());
  std::vector<std::vector<int>> linePlanes(prims.size());  // the clip index of each of lines[i]
  for (std::size_t m = 0; m < pairs.size(); ++m) {
    const Pair& p = pairs[m];
    if (sampled[m] != 1 || p.group->refused) continue;
    ++rep.polylines;
    for (const auto& [i, k] : {std::pair{p.lo, p.klo}, std::pair{p.hi, p.khi}}) {
      const HalfSpace& h = prims[std::size_t(i)].clip[std::size_t(k)];
      auto& pl = planes[std::size_t(i)];
      if (std::none_of(pl.begin(), pl.end(), [&](const HalfSpace& x) { return x.p == h.p; })) pl.push_back(h);
      // The piece's side of a plane is one boundary: an arc that two pieces across it both
      // end on (they overlap there, within the rounding of their corners) is drawn once.
      // At a budget the two pairs sample it to their own chord errors, so the two polylines
      // can differ: the finer one is kept. Where this was traced (bspline_volume_g1, piece
      // 2792) the finer one is the sampling of the small piece that holds the arc; the larger
      // one reaches the arc only at a corner and leaves it out of its own boundary as a spur
      // (boundary_strip.h).
      auto& mine = linePlanes[std::size_t(i)];
      auto& have = lines[std::size_t(i)];
      int same = -1;
      for (std::size_t l = 0; l < mine.size() && same < 0; ++l)
        if (mine[l] == k && sameArc(have[l], p.polyline)) same = int(l);
      if (same >= 0) {
        if (p.polyline.size() > have[std::size_t(same)].size()) have[std::size_t(same)] = p.polyline;
        continue;
      }
      mine.push_back(k);
      have.push_back(p.polyline);
    }
  }
  for (const auto& [key, g] : groups)
    if (!g.side[0].empty() && !g.side[1].empty() && g.refused) ++rep.refused_planes;
  std::vector<char> zipped(prims.size(), 0);
#pragma omp parallel for schedule(dynamic, 16)
  for (long li = 0; li < long(prims.size()); ++li) {
    const std::size_t i = std::size_t(li);
    if (lines[i].empty()) continue;
    PolylineTolerance tol;
    if (sampling.view) {
      tol.view = sampling.view;
      tol.pixels = sampling.pixels;
    } else {
      tol.world = sampling.chordError[i];
    }
    tol.samples = sampling.samples;
    zipped[i] =
        zipBoundaryStrip(*meshes[i], surfaceTriangles[i], planes[i], lines[i], prims[i].quadric.normalized(), tol) ? 1
                                                                                                                   : 2;
  }
  rep.rebuilt.assign(prims.size(), 0);
  for (std::size_t i = 0; i < prims.size(); ++i) {
    rep.zipped += zipped[i] == 1;
    rep.refused_pieces += zipped[i] == 2;
    rep.rebuilt[i] = zipped[i] == 1;
  }
  return rep;
}

}  // namespace qacc::tess
