// A piece's mesh made to end on its shared polylines (boundary_strip.h).
#include "modeling/tessellation/boundary_strip.h"

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <limits>
#include <map>
#include <optional>
#include <utility>

#include "modeling/tessellation/piece_boundary.h"    // onPlaneWithinRounding
#include "modeling/tessellation/screen_error.h"
#include "modeling/tessellation/surface_clipping.h"  // PointKey

namespace qacc::tess {

using Eigen::Vector3d;

namespace {

struct Path {
  std::vector<Vector3d> points;
  bool closed = false;
};

using Segment = std::pair<Vector3d, Vector3d>;

// An edge as its two ends in lexicographic order, ordered lexicographically: the key of the
// edge maps below, the same whichever way a triangle runs along it.
using EdgeKey = std::pair<Vector3d, Vector3d>;
EdgeKey edgeKey(const Vector3d& a, const Vector3d& b) { return lexLess(b, a) ? EdgeKey{b, a} : EdgeKey{a, b}; }
struct EdgeLess {
  bool operator()(const EdgeKey& a, const EdgeKey& b) const {
    if (a.first != b.first) return lexLess(a.first, b.first);
    return lexLess(a.second, b.second);
  }
};

// The segments joined where their ends are equal: open paths (from an end used once) and
// closed loops; std::nullopt when a point ends more than two segments.
std::optional<std::vector<Path>> chain(const std::vector<Segment>& segments) {
  std::map<Vector3d, std::vector<Vector3d>, PointKey> next;
  for (const auto& [a, b] : segments) {
    next[a].push_back(b);
    next[b].push_back(a);
  }
  for (const auto& [p, n] : next)
    if (n.size() > 2) return std::nullopt;
  std::map<Vector3d, bool, PointKey> used;
  std::vector<Path> out;
  auto walk = [&](const Vector3d& start) {
    Path path;
    Vector3d prev = start, at = start;
    path.points.push_back(start);
    used[start] = true;
    for (;;) {
      const std::vector<Vector3d>& n = next[at];
      const Vector3d* step = nullptr;
      for (const Vector3d& c : n)
        if (!used[c] && !(path.points.size() >= 2 && c == prev)) {
          step = &c;
          break;
        }
      if (!step) {
        // Back at the start: a loop.
        path.closed = path.points.size() >= 3 && std::find(n.begin(), n.end(), start) != n.end();
        break;
      }
      prev = at;
      at = *step;
      used[at] = true;
      path.points.push_back(at);
    }
    out.push_back(std::move(path));
  };
  for (const auto& [p, n] : next)
    if (n.size() == 1 && !used[p]) walk(p);
  for (const auto& [p, n] : next)
    if (!used[p]) walk(p);
  return out;
}

// The polylines' segments (of positive length), less those found twice: a segment on two of a
// piece's shared planes (the same two ends in two polylines) is where the piece is no wider
// than the rounding of its corners, and its two neighbours meet along it with nothing between;
// and less the spurs (below).
std::vector<Segment> undoubledSegments(const std::vector<std::vector<Vector3d>>& polylines) {
  std::map<EdgeKey, int, EdgeLess> count;
  std::vector<Segment> all;
  for (const auto& line : polylines)
    for (std::size_t i = 0; i + 1 < line.size(); ++i)
      if (line[i] != line[i + 1]) {
        all.push_back({line[i], line[i + 1]});
        ++count[edgeKey(line[i], line[i + 1])];
      }
  std::vector<Segment> out;
  for (const Segment& sg : all) {
    int& c = count[edgeKey(sg.first, sg.second)];
    if (c % 2 == 1) out.push_back(sg);
    c = 0;  // each segment once
  }
  // A spur: a segment from a junction (a point ending three or more segments) to a point
  // ending it alone, where a neighbour ends on an arc this piece reaches only at the junction
  // (they overlap there within the rounding of their corners): left out, while one is found.
  for (bool found = true; found;) {
    found = false;
    std::map<Vector3d, int, PointKey> degree;
    for (const auto& [a, b] : out) {
      ++degree[a];
      ++degree[b];
    }
    for (std::size_t i = 0; i < out.size() && !found; ++i) {
      const int da = degree[out[i].first], db = degree[out[i].second];
      if ((da == 1 && db >= 3) || (db == 1 && da >= 3)) {
        out.erase(out.begin() + std::ptrdiff_t(i));
        found = true;
      }
    }
  }
  return out;
}

// Cumulative arc length of a path, as fractions of its length (by index when it has none).
std::vector<double> arcFractions(const std::vector<Vector3d>& p) {
  std::vector<double> f(p.size(), 0.0);
  for (std::size_t i = 1; i < p.size(); ++i) f[i] = f[i - 1] + (p[i] - p[i - 1]).norm();
  const double total = f.empty() ? 0.0 : f.back();
  for (std::size_t i = 0; i < p.size(); ++i)
    f[i] = total > 0 ? f[i] / total : (p.size() > 1 ? double(i) / double(p.size() - 1) : 0.0);
  return f;
}

// The point at arc fraction t of a path.
Vector3d atFraction(const std::vector<Vector3d>& p, const std::vector<double>& f, double t) {
  for (std::size_t i = 1; i < p.size(); ++i)
    if (f[i] >= t) {
      const double w = f[i] > f[i - 1] ? (t - f[i - 1]) / (f[i] - f[i - 1]) : 0.0;
      return p[i - 1] + w * (p[i] - p[i - 1]);
    }
  return p.back();
}

// How far apart two paths run (from their starts, by arc fraction).
double pathDistance(const std::vector<Vector3d>& a, const std::vector<Vector3d>& b) {
  const std::vector<double> fa = arcFractions(a), fb = arcFractions(b);
  double d = 0;
  for (double t : {0.0, 0.25, 0.5, 0.75, 1.0}) d += (atFraction(a, fa, t) - atFraction(b, fb, t)).norm();
  return d;
}

// A loop as the open path from its point nearest `to` round to that point again, in the
// direction that runs nearest `along`.
std::vector<Vector3d> openLoop(const std::vector<Vector3d>& loop, const Vector3d& to, const std::vector<Vector3d>& along) {
  std::size_t start = 0;
  for (std::size_t i = 1; i < loop.size(); ++i)
    if ((loop[i] - to).squaredNorm() < (loop[start] - to).squaredNorm()) start = i;
  std::vector<Vector3d> fwd, bwd;
  for (std::size_t k = 0; k <= loop.size(); ++k) {
    fwd.push_back(loop[(start + k) % loop.size()]);
    bwd.push_back(loop[(start + loop.size() - k % loop.size()) % loop.size()]);
  }
  return pathDistance(fwd, along) <= pathDistance(bwd, along) ? fwd : bwd;
}

// Of the kept triangles (removed[t] == 0), only the largest set connected through shared
// edges stays: an island cut off by the removal (a triangle or two between the strips) would
// leave a second kept chain with no polyline of its own.
void removeAllButLargest(const TriangleMesh3& mesh, std::size_t nsurf, std::vector<char>& removed) {
  std::map<EdgeKey, std::vector<std::size_t>, EdgeLess> byEdge;
  auto pos = [&](std::size_t t, int k) -> const Vector3d& { return mesh.positions[std::size_t(mesh.triangles[t][k])]; };
  for (std::size_t t = 0; t < nsurf; ++t) {
    if (removed[t]) continue;
    for (int k = 0; k < 3; ++k) {
      const Vector3d &a = pos(t, k), &b = pos(t, (k + 1) % 3);
      byEdge[edgeKey(a, b)].push_back(t);
    }
  }
  std::vector<int> component(nsurf, -1);
  std::vector<std::size_t> sizes;
  for (std::size_t t0 = 0; t0 < nsurf; ++t0) {
    if (removed[t0] || component[t0] >= 0) continue;
    const int c = int(sizes.size());
    sizes.push_back(0);
    std::vector<std::size_t> stack{t0};
    component[t0] = c;
    while (!stack.empty()) {
      const std::size_t t = stack.back();
      stack.pop_back();
      ++sizes.back();
      for (int k = 0; k < 3; ++k) {
        const Vector3d &a = pos(t, k), &b = pos(t, (k + 1) % 3);
        for (std::size_t u : byEdge[edgeKey(a, b)])
          if (component[u] < 0) {
            component[u] = c;
            stack.push_back(u);
          }
      }
    }
  }
  if (sizes.size() <= 1) return;
  const int largest = int(std::max_element(sizes.begin(), sizes.end()) - sizes.begin());
  for (std::size_t t = 0; t < nsurf; ++t)
    if (!removed[t] && component[t] != largest) removed[t] = 1;
}

struct Strip {
  const Quadric& q;
  int winding;  // +1: triangles wound counter-clockwise about their normals, -1: clockwise
  const std::map<Vector3d, Vector3d, PointKey>& keptNormals;
  TriangleMesh3& out;

  int gradientSign;  // +1: the piece's normals point along the quadric's gradient, -1: against
  const std::vector<HalfSpace>& sharedPlanes;

  Vector3d normalAt(const Vector3d& p) const {
    auto it = keptNormals.find(p);
    if (it != keptNormals.end()) return it->second;
    const Vector3d g = q.gradient(p);
    return g.norm() > 0 ? Vector3d(double(gradientSign) * g.normalized()) : Vector3d::UnitZ();
  }
  void triangle(const Vector3d& a, const Vector3d& b, const Vector3d& c) {
    if (a == b || b == c || a == c) return;
    const Vector3d na = normalAt(a), nb = normalAt(b), nc = normalAt(c);
    const bool flip = winding * (b - a).cross(c - a).dot(na + nb + nc) < 0;
    const int base = int(out.positions.size());
    for (const auto& [p, n] : {std::pair{a, na}, flip ? std::pair{c, nc} : std::pair{b, nb},
                               flip ? std::pair{b, nb} : std::pair{c, nc}}) {
      out.positions.push_back(p);
      out.normals.push_back(n);
    }
    out.triangles.push_back({base, base + 1, base + 2});
  }
  // A closed loop (no point repeated) triangulated with the fewest triangles in a shared plane,
  // then the least total area (dynamic programming over its sub-polygons). A triangle whose
  // three vertices lie on one of the piece's shared planes lies in that plane, not on the
  // surface, which crosses the plane only along the shared curve (the sliver between an arc's
  // vertices and its chord, say); the piece across, ending on the same vertices, can draw the
  // same triangle, and the chord is then used by four triangles.
  void polygon(const std::vector<Vector3d>& p) {
    const std::size_t n = p.size();
    if (n < 3) return;
    std::vector<std::uint64_t> on(n, 0);  // the shared planes (the first 64) each point lies on
    for (std::size_t i = 0; i < n; ++i)
      for (std::size_t h = 0; h < std::min<std::size_t>(sharedPlanes.size(), 64); ++h)
        if (onPlaneWithinRounding(sharedPlanes[h], p[i])) on[i] |= std::uint64_t(1) << h;
    std::vector<double> w(n * n, 0.0);
    std::vector<std::size_t> flat(n * n, 0), arg(n * n, 0);
    for (std::size_t len = 2; len < n; ++len)
      for (std::size_t i = 0; i + len < n; ++i) {
        const std::size_t j = i + len;
        double best = 1e300;
        std::size_t bestFlat = n;
        for (std::size_t k = i + 1; k < j; ++k) {
          const std::size_t f = flat[i * n + k] + flat[k * n + j] + ((on[i] & on[k] & on[j]) != 0 ? 1 : 0);
          const double c = w[i * n + k] + w[k * n + j] + 0.5 * (p[k] - p[i]).cross(p[j] - p[i]).norm();
          if (f < bestFlat || (f == bestFlat && c < best)) {
            best = c;
            bestFlat = f;
            arg[i * n + j] = k;
          }
        }
        w[i * n + j] = best;
        flat[i * n + j] = bestFlat;
      }
    std::vector<std::pair<std::size_t, std::size_t>> todo{{0, n - 1}};
    while (!todo.empty()) {
      const auto [i, j] = todo.back();
      todo.pop_back();
      if (j < i + 2) continue;
      const std::size_t k = arg[i * n + j];
      triangle(p[i], p[k], p[j]);
      todo.push_back({i, k});
      todo.push_back({k, j});
    }
  }
  // The error of new triangle t, measured as the scene's report measures it (the samples of
  // measurePixelError in a view, of measureChordError otherwise), against the tolerance.
  double excess(std::size_t t, const PolylineTolerance& tol) const {
    if (tol.view && tol.pixels > 0)
      return measurePixelError(out, q, *tol.view, t, 1, tol.samples).max / tol.pixels;
    return tol.world > 0 ? measureChordError(out, q, t, 1, tol.samples).max / tol.world : 0.0;
  }
  // Until every new triangle is within the tolerance (by excess()), or kStripRefinements
  // rounds, or the strip has kStripGrowth times as many triangles as it had or as it replaced: each triangle over it is split, at most one split per triangle and round. Its
  // longest edge shared with another new triangle is halved in both (the midpoint moved onto
  // the surface); a triangle with no such edge (all three on the polylines or the kept chains,
  // which are never split, so both sides keep their vertices) gets its centroid, moved onto
  // the surface, as a third vertex of three triangles.
  // Returns the largest excess() left (at most 1 when every new triangle is within the tolerance).
  double refine(const PolylineTolerance& tol, std::size_t replaced) {
    auto at = [&](std::size_t t, int k) -> const Vector3d& { return out.positions[std::size_t(out.triangles[t][k])]; };
    // A point of the surface near m: its closest point, unless that lies farther than
    // `reach` (another sheet, or no convergence).
    auto ontoSurface = [&](const Vector3d& m, double reach, Vector3d& p) {
      p = closestPointOnQuadric(q, m);
      return p.allFinite() && (p - m).norm() <= reach;
    };
    // A triangle no longer than the tolerance (its longest edge, in pixels in a view) is not
    // split: whatever its measured error, halving it would not be seen.
    auto longerThanTolerance = [&](std::size_t t) {
      double longest = 0;
      for (int k = 0; k < 3; ++k) {
        const Vector3d &a = at(t, k), &b = at(t, (k + 1) % 3);
        longest = std::max(longest, tol.view && tol.pixels > 0 ? (tol.view->project(a) - tol.view->project(b)).norm()
                                                               : (b - a).norm());
      }
      return longest > (tol.view && tol.pixels > 0 ? tol.pixels : tol.world);
    };
    // excess() of each triangle, measured once: a triangle a round leaves as it was keeps its
    // value (NaN: not measured yet), so a round measures only the triangles it made.
    const double unmeasured = std::numeric_limits<double>::quiet_NaN();
    std::vector<double> measured(out.triangles.size(), unmeasured);
    auto excessOf = [&](std::size_t t) {
      if (std::isnan(measured[t])) measured[t] = excess(t, tol);
      return measured[t];
    };
    const std::size_t budget = kStripGrowth * std::max<std::size_t>({out.triangles.size(), replaced, 1});
    for (int round = 0; round < kStripRefinements && out.triangles.size() < budget; ++round) {
      std::vector<std::size_t> over;
      for (std::size_t t = 0; t < out.triangles.size(); ++t)
        if (longerThanTolerance(t) && excessOf(t) > 1.0) over.push_back(t);
      if (over.empty()) return 1.0;
      // The triangles using each edge, in triangle order: the (edge, triangle) pairs sorted
      // stably by edge, an edge's run found by binary search (what a std::map of vectors
      // gives, without an allocation per edge).
      using EdgeUse = std::pair<EdgeKey, std::size_t>;  // an edge and a triangle using it
      std::vector<EdgeUse> uses;
      uses.reserve(3 * out.triangles.size());
      for (std::size_t t = 0; t < out.triangles.size(); ++t)
        for (int k = 0; k < 3; ++k) uses.emplace_back(edgeKey(at(t, k), at(t, (k + 1) % 3)), t);
      const auto byEdge = [](const EdgeUse& x, const EdgeUse& y) { return EdgeLess{}(x.first, y.first); };
      std::stable_sort(uses.begin(), uses.end(), byEdge);
      // The triangles of edge e: at most the first two, and how many there are.
      const auto usesOf = [&](const EdgeKey& e, std::size_t ts[2]) {
        const auto range = std::equal_range(uses.begin(), uses.end(), EdgeUse{e, 0}, byEdge);
        const std::size_t n = std::size_t(range.second - range.first);
        for (std::size_t i = 0; i < std::min<std::size_t>(n, 2); ++i) ts[i] = range.first[std::ptrdiff_t(i)].second;
        return n;
      };
      std::vector<char> busy(out.triangles.size(), 0);
      std::map<EdgeKey, Vector3d, EdgeLess> mid;
      std::map<std::size_t, Vector3d> centre;
      for (std::size_t t : over) {
        if (busy[t]) continue;
        int best = -1;
        double bestLength = -1;
        bool anyShared = false;
        for (int k = 0; k < 3; ++k) {
          const Vector3d &a = at(t, k), &b = at(t, (k + 1) % 3);
          std::size_t ts[2];
          if (usesOf(edgeKey(a, b), ts) != 2) continue;
          anyShared = true;
          const std::size_t other = ts[0] == t ? ts[1] : ts[0];
          if (busy[other] || (b - a).norm() <= bestLength) continue;
          best = k;
          bestLength = (b - a).norm();
        }
        Vector3d p;
        if (best >= 0) {
          const Vector3d &a = at(t, best), &b = at(t, (best + 1) % 3);
          if (!ontoSurface(0.5 * (a + b), 0.5 * (b - a).norm(), p)) continue;
          std::size_t ts[2];
          usesOf(edgeKey(a, b), ts);  // two: best is a shared edge
          busy[ts[0]] = busy[ts[1]] = 1;
          mid.emplace(edgeKey(a, b), p);
        } else if (!anyShared) {
          const Vector3d c = (at(t, 0) + at(t, 1) + at(t, 2)) / 3.0;
          const double size = std::max({(at(t, 1) - at(t, 0)).norm(), (at(t, 2) - at(t, 1)).norm(),
                                        (at(t, 0) - at(t, 2)).norm()});
          if (!ontoSurface(c, 0.5 * size, p)) continue;
          busy[t] = 1;
          centre.emplace(t, p);
        }
      }
      if (mid.empty() && centre.empty()) break;
      TriangleMesh3 next;
      std::swap(next, out);
      std::vector<double> previous;  // next's measured excesses; measured is out's, refilled by emit
      std::swap(previous, measured);
      for (std::size_t t = 0; t < next.triangles.size(); ++t) {
        const Vector3d v[3] = {next.positions[std::size_t(next.triangles[t][0])],
                               next.positions[std::size_t(next.triangles[t][1])],
                               next.positions[std::size_t(next.triangles[t][2])]};
        const Vector3d n[3] = {next.normals[std::size_t(next.triangles[t][0])],
                               next.normals[std::size_t(next.triangles[t][1])],
                               next.normals[std::size_t(next.triangles[t][2])]};
        auto emit = [&](const Vector3d& a, const Vector3d& na, const Vector3d& b, const Vector3d& nb,
                        const Vector3d& c, const Vector3d& nc, double excessKnown) {
          const int base = int(out.positions.size());
          out.positions.insert(out.positions.end(), {a, b, c});
          out.normals.insert(out.normals.end(), {na, nb, nc});
          out.triangles.push_back({base, base + 1, base + 2});
          measured.push_back(excessKnown);
        };
        if (auto it = centre.find(t); it != centre.end()) {
          const Vector3d& p = it->second;
          const Vector3d np = normalAt(p);
          for (int k = 0; k < 3; ++k) emit(v[k], n[k], v[(k + 1) % 3], n[(k + 1) % 3], p, np, unmeasured);
          continue;
        }
        int split = -1;
        Vector3d p;
        for (int k = 0; k < 3 && split < 0; ++k) {
          auto it = mid.find(edgeKey(v[k], v[(k + 1) % 3]));
          if (it != mid.end()) {
            split = k;
            p = it->second;
          }
        }
        if (split < 0) {  // unchanged: its vertices in the same order, so the same excess()
          emit(v[0], n[0], v[1], n[1], v[2], n[2], previous[t]);
          continue;
        }
        const int a = split, b = (split + 1) % 3, c = (split + 2) % 3;
        const Vector3d np = normalAt(p);
        emit(v[a], n[a], p, np, v[c], n[c], unmeasured);
        emit(p, np, v[b], n[b], v[c], n[c], unmeasured);
      }
    }
    double worst = 0;
    for (std::size_t t = 0; t < out.triangles.size(); ++t)
      if (longerThanTolerance(t)) worst = std::max(worst, excessOf(t));
    return worst;
  }
  // Kept chain `in` and new boundary `o`, both from the same end.
  void zip(const std::vector<Vector3d>& in, const std::vector<Vector3d>& o) {
    const std::vector<double> fi = arcFractions(in), fo = arcFractions(o);
    std::size_t a = 0, b = 0;
    while (a + 1 < in.size() || b + 1 < o.size()) {
      const bool onO = a + 1 >= in.size() || (b + 1 < o.size() && fo[b + 1] <= fi[a + 1]);
      if (onO) {
        triangle(in[a], o[b], o[b + 1]);
        ++b;
      } else {
        triangle(in[a], o[b], in[a + 1]);
        ++a;
      }
    }
  }
};


// Open new boundary paths joined to the chains of what is left (kept chains and the piece's
// own edges on unshared planes), each end of a path to the nearest end of a chain (that end
// replaced by the path's when within kMergeEnds, else joined by an edge); the loops this
// closes triangulated one by one. False when a path is closed, a loop does not close or
// holds no new boundary, or is longer than kMaxLoopPoints.
bool fillLoops(const std::vector<Path>& out, const std::vector<Segment>& inner, const std::vector<Segment>& own,
               Strip& s) {
  std::vector<Segment> rest = inner;
  rest.insert(rest.end(), own.begin(), own.end());
  const auto left = chain(rest);
  if (!left) return false;
  std::vector<Vector3d> ends;
  for (const Path& k : *left)
    if (!k.closed) {
      ends.push_back(k.points.front());
      ends.push_back(k.points.back());
    }
  std::vector<Segment> all = rest;
  std::map<Vector3d, bool, PointKey> isNew;
  for (const Path& o : out) {
    if (o.closed) return false;
    for (std::size_t i = 0; i + 1 < o.points.size(); ++i) all.push_back({o.points[i], o.points[i + 1]});
    for (const Vector3d& p : o.points) isNew[p] = true;
    for (const Vector3d* e : {&o.points.front(), &o.points.back()}) {
      std::size_t best = ends.size();
      for (std::size_t k = 0; k < ends.size(); ++k)
        if (best == ends.size() || (ends[k] - *e).squaredNorm() < (ends[best] - *e).squaredNorm()) best = k;
      if (best == ends.size()) return false;
      const Vector3d k = ends[best];
      ends.erase(ends.begin() + std::ptrdiff_t(best));
      if (k == *e) continue;
      if ((k - *e).norm() <= kMergeEnds * (1 + e->norm())) {
        // The piece's own corner, within its gap to the neighbour: it becomes the path's end
        // (no sliver edge between the two on the shared plane).
        for (Segment& sgm : all) {
          if (sgm.first == k) sgm.first = *e;
          if (sgm.second == k) sgm.second = *e;
        }
      } else {
        all.push_back({*e, k});
      }
    }
  }
  const auto loops = chain(all);
  if (!loops) return false;
  for (const Path& l : *loops) {
    if (!l.closed || l.points.size() > kMaxLoopPoints) return false;
    if (std::none_of(l.points.begin(), l.points.end(), [&](const Vector3d& p) { return isNew.count(p) > 0; }))
      return false;
  }
  for (const Path& l : *loops) s.polygon(l.points);
  return true;
}


// zipBoundaryStrip with the triangles that touch a shared plane removed (removeAll false), or
// with every surface triangle removed, the piece rebuilt from its polylines and its own edges
// on unshared planes alone (removeAll true).
struct Rebuilt {
  TriangleMesh3 mesh;
  std::size_t surface = 0;
  double excess = 0;  // the strip's largest error over the tolerance (Strip::refine)
};

// The piece's kept surface triangles (the first nsurf of mesh not removed), the strip, then
// its caps (the triangles after nsurf).
Rebuilt assemble(const TriangleMesh3& mesh, std::size_t nsurf, const std::vector<char>& removed,
                 const TriangleMesh3& strip, double excess) {
  TriangleMesh3 result;
  auto copy = [&](std::size_t t) {
    const int base = int(result.positions.size());
    for (int k = 0; k < 3; ++k) {
      result.positions.push_back(mesh.positions[std::size_t(mesh.triangles[t][k])]);
      result.normals.push_back(mesh.normals[std::size_t(mesh.triangles[t][k])]);
    }
    result.triangles.push_back({base, base + 1, base + 2});
  };
  for (std::size_t t = 0; t < nsurf; ++t)
    if (!removed[t]) copy(t);
  result.append(strip);
  Rebuilt r;
  r.surface = result.triangles.size();
  for (std::size_t t = nsurf; t < mesh.triangles.size(); ++t) copy(t);
  r.mesh = std::move(result);
  r.excess = excess;
  return r;
}

std::optional<Rebuilt> zipStrip(const TriangleMesh3& mesh, std::size_t surface,
                                const std::vector<HalfSpace>& sharedPlanes,
                                const std::vector<std::vector<Vector3d>>& polylines, const Quadric& q,
                                const PolylineTolerance& tol, bool removeAll) {
  if (polylines.empty()) return std::nullopt;
  const std::size_t nsurf = std::min(surface, mesh.triangles.size());
  auto pos = [&](std::size_t t, int k) -> const Vector3d& { return mesh.positions[std::size_t(mesh.triangles[t][k])]; };
  auto touches = [&](const Vector3d& x) {
    for (const HalfSpace& h : sharedPlanes)
      if (onPlaneWithinRounding(h, x)) return true;
    return false;
  };
  std::vector<char> removed(nsurf, removeAll ? 1 : 0);
  if (!removeAll) {
    for (std::size_t t = 0; t < nsurf; ++t)
      for (int k = 0; k < 3 && !removed[t]; ++k) removed[t] = touches(pos(t, k));
    removeAllButLargest(mesh, nsurf, removed);
  }

  // Edges of the kept triangles used once that a removed triangle uses too: the inner chains.
  std::map<EdgeKey, int, EdgeLess> keptUse;
  std::map<EdgeKey, bool, EdgeLess> removedEdge;
  std::map<Vector3d, Vector3d, PointKey> keptNormals;
  double windingSum = 0;
  for (std::size_t t = 0; t < nsurf; ++t)
    for (int k = 0; k < 3; ++k) {
      const EdgeKey e = edgeKey(pos(t, k), pos(t, (k + 1) % 3));
      if (removed[t]) {
        removedEdge[e] = true;
      } else {
        ++keptUse[e];
        keptNormals.emplace(pos(t, k), mesh.normals[std::size_t(mesh.triangles[t][k])]);
      }
    }
  double gradientSum = 0;
  for (std::size_t v = 0; v < mesh.positions.size(); ++v)
    gradientSum += q.gradient(mesh.positions[v]).dot(mesh.normals[v]) >= 0 ? 1 : -1;
  for (std::size_t t = 0; t < nsurf; ++t) {
    const Vector3d n = mesh.normals[std::size_t(mesh.triangles[t][0])] + mesh.normals[std::size_t(mesh.triangles[t][1])] +
                       mesh.normals[std::size_t(mesh.triangles[t][2])];
    windingSum += (pos(t, 1) - pos(t, 0)).cross(pos(t, 2) - pos(t, 0)).dot(n) > 0 ? 1 : -1;
  }
  std::map<EdgeKey, int, EdgeLess> allUse;
  for (std::size_t t = 0; t < nsurf; ++t)
    for (int k = 0; k < 3; ++k) ++allUse[edgeKey(pos(t, k), pos(t, (k + 1) % 3))];
  auto onSharedPlane = [&](const EdgeKey& e) {
    for (const HalfSpace& h : sharedPlanes)
      if (onPlaneWithinRounding(h, e.first) && onPlaneWithinRounding(h, e.second)) return true;
    return false;
  };
  std::vector<Segment> inner;
  for (const auto& [e, uses] : keptUse)
    if (uses == 1 && removedEdge.count(e)) inner.push_back(e);
  const std::vector<Segment> outer = undoubledSegments(polylines);
  if (outer.empty()) {
    // Every polyline segment lies on two of the piece's shared planes: the piece is a sliver
    // (its corners met when they were snapped, or its arcs on two planes have one chord to
    // the tolerance). When all its surface lies within the tolerance (or kMergeEnds) of those
    // segments, its neighbours meet along them and the piece draws nothing; else it is refused.
    // Its vertices and its triangles' centroids (the chords may turn a corner, so a triangle
    // with its vertices on them can still cover surface away from them).
    for (std::size_t t = 0; t < nsurf; ++t)
      for (int k = 0; k < 4; ++k) {
        const Vector3d x = k < 3 ? pos(t, k) : Vector3d((pos(t, 0) + pos(t, 1) + pos(t, 2)) / 3.0);
        const double d = distanceToSegments(x, polylines);
        const bool within = d <= kMergeEnds * (1 + x.norm()) || (tol.world > 0 && d <= tol.world) ||
                            (tol.view && tol.pixels > 0 && d * tol.view->pixelsPerUnit(x) <= tol.pixels);
        if (!within) return std::nullopt;
      }
    return assemble(mesh, nsurf, std::vector<char>(nsurf, 1), TriangleMesh3(), 0.0);
  }
  const auto in = chain(inner);
  auto out = chain(outer);
  // With no open kept chain to end on, nor any edge of the piece's own on unshared planes
  // (which the fallback, fillLoops, would join the path's ends to), an open path whose ends
  // are within kMergeEnds of each other (an arc of the shared curve too short for its ends to
  // be found, missing alike on both sides) is closed by the edge between them.
  const bool ownEdges = std::any_of(allUse.begin(), allUse.end(), [&](const auto& eu) {
    return eu.second == 1 && removedEdge.count(eu.first) && !onSharedPlane(eu.first);
  });
  if (in && out && !ownEdges && std::none_of(in->begin(), in->end(), [](const Path& c) { return !c.closed; }))
    for (Path& o : *out) {
      const Vector3d &f = o.points.front(), &b = o.points.back();
      if (!o.closed && o.points.size() >= 3 && (b - f).norm() <= kMergeEnds * (1 + f.norm())) o.closed = true;
    }
  if (!in || !out || out->empty()) return std::nullopt;

  TriangleMesh3 strip;
  Strip s{q, windingSum >= 0 ? 1 : -1, keptNormals, strip, gradientSum >= 0 ? 1 : -1, sharedPlanes};
  // Each new boundary path paired with a kept chain (zipped), or a closed one with nothing
  // kept fanned.
  auto pairUp = [&]() -> bool {
    std::vector<bool> paired(in->size(), false);
    for (const Path& o : *out) {
      if (o.closed) {
        // A loop: the kept loop nearest it, or a fan when nothing is kept.
        int best = -1;
        for (std::size_t k = 0; k < in->size(); ++k)
          if ((*in)[k].closed && !paired[k]) best = best < 0 ? int(k) : -2;
        if (best == -2) return false;
        if (best < 0) {
          if (!in->empty()) return false;
          if (o.points.size() <= kMaxLoopPoints) {
            s.polygon(o.points);
            continue;
          }
          Vector3d c = Vector3d::Zero();
          for (const Vector3d& p : o.points) c += p;
          c = closestPointOnQuadric(q, c / double(o.points.size()));
          std::vector<Vector3d> ring = o.points;
          ring.push_back(o.points.front());
          // Wound like the other triangles of the piece, by the surface's gradient.
          for (std::size_t i = 0; i + 1 < ring.size(); ++i) s.triangle(c, ring[i], ring[i + 1]);
          continue;
        }
        paired[std::size_t(best)] = true;
        std::vector<Vector3d> ring = o.points;
        ring.push_back(o.points.front());
        const std::vector<Vector3d> kept = openLoop((*in)[std::size_t(best)].points, ring.front(), ring);
        s.zip(kept, ring);
        continue;
      }
      // An open path: the open chain whose ends are nearest its ends.
      int best = -1;
      bool reversed = false;
      double bestDist = 1e300;
      for (std::size_t k = 0; k < in->size(); ++k) {
        const Path& c = (*in)[k];
        if (c.closed || paired[k]) continue;
        const double fwd = (c.points.front() - o.points.front()).norm() + (c.points.back() - o.points.back()).norm();
        const double bwd = (c.points.back() - o.points.front()).norm() + (c.points.front() - o.points.back()).norm();
        if (std::min(fwd, bwd) < bestDist) {
          bestDist = std::min(fwd, bwd);
          best = int(k);
          reversed = bwd < fwd;
        }
      }
      if (best < 0) return false;
      paired[std::size_t(best)] = true;
      std::vector<Vector3d> kept = (*in)[std::size_t(best)].points;
      if (reversed) std::reverse(kept.begin(), kept.end());
      s.zip(kept, o.points);
    }
    for (bool p : paired)
      if (!p) return false;
    return true;
  };
  if (!pairUp()) {
    // The region the removal left, bounded by loops of kept chains, the piece's own edges on
    // planes no other piece shares, and the polylines: each loop triangulated on its own.
    strip = TriangleMesh3();
    std::vector<Segment> own;
    for (const auto& [e, uses] : allUse)
      if (uses == 1 && removedEdge.count(e) && !onSharedPlane(e)) own.push_back(e);
    const bool twoLoops = out->size() == 2 && (*out)[0].closed && (*out)[1].closed;
    if (twoLoops) {
      // A band (the surface enters the region through one loop and leaves through the
      // other): zipped from loop to loop, nothing kept between them.
      std::vector<Vector3d> a = (*out)[0].points, b = (*out)[1].points;
      a.push_back(a.front());
      b = openLoop(b, a.front(), a);
      s.zip(b, a);
      std::fill(removed.begin(), removed.end(), 1);
    } else if (!fillLoops(*out, inner, own, s)) {
      return std::nullopt;
    }
  }

  const double excess = s.refine(tol, std::size_t(std::count(removed.begin(), removed.end(), char(1))));
  return assemble(mesh, nsurf, removed, strip, excess);
}

}  // namespace

double distanceToSegments(const Vector3d& x, const std::vector<std::vector<Vector3d>>& polylines) {
  double best = 1e300;
  for (const auto& line : polylines)
    for (std::size_t i = 0; i < line.size(); ++i) {
      const Vector3d& a = line[i];
      const Vector3d& b = line[std::min(i + 1, line.size() - 1)];
      const Vector3d d = b - a;
      const double len2 = d.squaredNorm();
      const double t = len2 > 0 ? std::clamp((x - a).dot(d) / len2, 0.0, 1.0) : 0.0;
      best = std::min(best, (x - (a + t * d)).norm());
    }
  return best;
}

bool zipBoundaryStrip(TriangleMesh3& mesh, std::size_t& surface, const std::vector<HalfSpace>& sharedPlanes,
                      const std::vector<std::vector<Vector3d>>& polylines, const Quadric& q,
                      const PolylineTolerance& tol) {
  std::optional<Rebuilt> best = zipStrip(mesh, surface, sharedPlanes, polylines, q, tol, false);
  if (!best || best->excess > 1.0) {
    std::optional<Rebuilt> whole = zipStrip(mesh, surface, sharedPlanes, polylines, q, tol, true);
    if (whole && (!best || whole->excess < best->excess)) best = std::move(whole);
  }
  if (!best) return false;
  mesh = std::move(best->mesh);
  surface = best->surface;
  return true;
}

}  // namespace qacc::tess
