#include "modeling/tessellation/solid_caps.h"

#include <algorithm>
#include <array>
#include <cmath>
#include <map>

namespace qacc::tess {

namespace {

// Ear clipping of a simple polygon given in 2-D (counter-clockwise); appends index triples.
// Returns false when no ear can be found (self-intersecting or degenerate input).
bool earClip(const std::vector<Vector2d>& pts, std::vector<std::array<int, 3>>& out) {
  std::vector<int> idx(pts.size());
  for (std::size_t i = 0; i < pts.size(); ++i) idx[i] = int(i);
  auto cross = [](const Vector2d& o, const Vector2d& a, const Vector2d& b) {
    return (a - o).x() * (b - o).y() - (a - o).y() * (b - o).x();
  };
  while (idx.size() > 3) {
    bool found = false;
    const std::size_t n = idx.size();
    for (std::size_t i = 0; i < n && !found; ++i) {
      const int ip = idx[(i + n - 1) % n], ic = idx[i], in = idx[(i + 1) % n];
      const Vector2d &A = pts[std::size_t(ip)], &B = pts[std::size_t(ic)], &C = pts[std::size_t(in)];
      if (cross(A, B, C) <= 0) continue;  // reflex or flat
      bool empty = true;
      for (std::size_t k = 0; k < n && empty; ++k) {
        const int o = idx[k];
        if (o == ip || o == ic || o == in) continue;
        const Vector2d& X = pts[std::size_t(o)];
        if (X == A || X == B || X == C) continue;
        if (cross(A, B, X) >= 0 && cross(B, C, X) >= 0 && cross(C, A, X) >= 0) empty = false;
      }
      if (!empty) continue;
      out.push_back({ip, ic, in});
      idx.erase(idx.begin() + std::ptrdiff_t(i));
      found = true;
    }
    if (!found) return false;
  }
  if (idx.size() == 3) out.push_back({idx[0], idx[1], idx[2]});
  return true;
}

// Corners of the cap's polygon on plane k: polytope vertices on this plane inside the
// solid (f <= 0), with the tags of the clip planes they lie on.
struct CapCorners {
  std::vector<Vector3d> points;
  std::vector<unsigned> tags;
};

CapCorners capCorners(unsigned kbit, const std::vector<HalfSpace>& planes, const std::vector<Vector3d>& polytope,
                      const Quadric& q) {
  CapCorners c;
  for (const auto& v : polytope) {
    unsigned t = 0;
    for (std::size_t m = 0; m < planes.size() && m < 32; ++m) {
      const double mag = planes[m].p.head<3>().cwiseAbs().dot(v.cwiseAbs()) + std::abs(planes[m].p[3]);
      if (std::abs(planes[m].eval(v)) <= 1e-9 * mag) t |= 1u << m;
    }
    // Only corners inside the solid (f <= 0) bound the cap.
    if ((t & kbit) && q.eval(v) <= 1e-9 * (1 + v.squaredNorm())) {
      c.points.push_back(v);
      c.tags.push_back(t);
    }
  }
  return c;
}

// Chains of segments followed end to start, open chains (whose start is no segment's end)
// first.
std::vector<std::vector<std::size_t>> capChains(const std::vector<CapSegment>& segs) {
  std::map<Vector3d, std::size_t, PointKey> startAt;  // segment starting at a point
  for (std::size_t i = 0; i < segs.size(); ++i) startAt.emplace(segs[i].a, i);
  std::map<Vector3d, int, PointKey> endCount;
  for (const auto& sg : segs) endCount[sg.b]++;
  std::vector<char> used(segs.size(), 0);
  std::vector<std::vector<std::size_t>> chains;
  std::vector<std::size_t> order;
  for (std::size_t i = 0; i < segs.size(); ++i)
    if (!endCount.count(segs[i].a)) order.push_back(i);
  for (std::size_t i = 0; i < segs.size(); ++i) order.push_back(i);
  for (std::size_t s0 : order) {
    if (used[s0]) continue;
    std::vector<std::size_t> chain;
    std::size_t cur = s0;
    while (!used[cur]) {
      used[cur] = 1;
      chain.push_back(cur);
      auto it = startAt.find(segs[cur].b);
      if (it == startAt.end()) break;
      cur = it->second;
    }
    chains.push_back(chain);
  }
  return chains;
}

// The boundary of the cap between open chains: from the end of chain c, walk along the
// boundary of the cap's polygon (plane k ∩ the other clip half-spaces) with the interior on
// the left — along the line k ∩ j to the nearest chain start on it, turning at the polygon's
// corners (appended to the loop) — or, when no walk is possible, jump to the nearest chain
// start. Returns the next chain, or chains.size() when there is none.
std::size_t walkToNextChain(std::size_t c0, std::size_t c, const std::vector<std::vector<std::size_t>>& chains,
                            const std::vector<char>& chainUsed, const std::vector<CapSegment>& segs,
                            const CapCorners& corners, const std::vector<HalfSpace>& planes, unsigned kbit,
                            const Vector3d& n, std::vector<Vector3d>& loop) {
  const CapSegment& last = segs[chains[c].back()];
  loop.push_back(last.b);
  Vector3d e = last.b;
  unsigned etags = last.tb & ~kbit;
  std::size_t pick = chains.size();
  for (int turn = 0; turn < 64 && pick == chains.size(); ++turn) {
    int j = -1;
    for (std::size_t m = 0; m < planes.size() && m < 32; ++m)
      if (etags & (1u << m)) {
        j = int(m);
        break;
      }
    if (j < 0) break;
    const Vector3d dir = n.cross(planes[std::size_t(j)].p.head<3>().normalized());
    const double eps = 1e-12 * (1 + e.norm());
    double best = 1e300;
    int bestChain = -1, bestCorner = -1;
    for (std::size_t d = 0; d < chains.size(); ++d) {
      if (chainUsed[d] && d != c0) continue;
      const CapSegment& first = segs[chains[d].front()];
      if (!(first.ta & (1u << j))) continue;
      const double along = (first.a - e).dot(dir);
      if (along > eps && along < best) {
        best = along;
        bestChain = int(d);
      }
    }
    for (std::size_t v = 0; v < corners.points.size(); ++v) {
      if (!(corners.tags[v] & (1u << j))) continue;
      const double along = (corners.points[v] - e).dot(dir);
      if (along > eps && along < best) {
        best = along;
        bestChain = -1;
        bestCorner = int(v);
      }
    }
    if (bestChain >= 0) {
      pick = std::size_t(bestChain);
    } else if (bestCorner >= 0) {
      e = corners.points[std::size_t(bestCorner)];
      loop.push_back(e);
      etags = corners.tags[std::size_t(bestCorner)] & ~kbit & ~(1u << j);
    } else {
      break;
    }
  }
  if (pick == chains.size()) {  // no walk possible: close to the nearest chain start
    double best = 1e300;
    for (std::size_t d = 0; d < chains.size(); ++d) {
      if (chainUsed[d] && d != c0) continue;
      const double dist = (segs[chains[d].front()].a - e).norm();
      if (dist < best) {
        best = dist;
        pick = d;
      }
    }
  }
  return pick;
}

// The loop without consecutive duplicates (nor a last point equal to the first).
std::vector<Vector3d> withoutRepeats(const std::vector<Vector3d>& loop) {
  std::vector<Vector3d> clean;
  for (const auto& p : loop)
    if (clean.empty() || !(clean.back() == p)) clean.push_back(p);
  while (clean.size() > 1 && clean.front() == clean.back()) clean.pop_back();
  return clean;
}

// Chains joined into closed loops (open ones through walkToNextChain); loops of at least 3 points.
std::vector<std::vector<Vector3d>> capLoops(const std::vector<std::vector<std::size_t>>& chains,
                                            const std::vector<CapSegment>& segs, const CapCorners& corners,
                                            const std::vector<HalfSpace>& planes, unsigned kbit, const Vector3d& n) {
  std::vector<char> chainUsed(chains.size(), 0);
  std::vector<std::vector<Vector3d>> loops;
  for (std::size_t c0 = 0; c0 < chains.size(); ++c0) {
    if (chainUsed[c0]) continue;
    std::vector<Vector3d> loop;
    std::size_t c = c0;
    for (int guard = 0; guard <= int(chains.size()); ++guard) {
      chainUsed[c] = 1;
      for (std::size_t si : chains[c]) loop.push_back(segs[si].a);
      if (segs[chains[c].back()].b == segs[chains[c0].front()].a) break;  // closed
      const std::size_t pick = walkToNextChain(c0, c, chains, chainUsed, segs, corners, planes, kbit, n, loop);
      if (pick == c0 || pick == chains.size()) break;
      c = pick;
    }
    std::vector<Vector3d> clean = withoutRepeats(loop);
    if (clean.size() >= 3) loops.push_back(clean);
  }
  return loops;
}

void appendCapTriangle(const Vector3d& a, const Vector3d& b, const Vector3d& c, const Vector3d& n, TriangleMesh3& mesh) {
  const int base = int(mesh.positions.size());
  mesh.positions.insert(mesh.positions.end(), {a, b, c});
  mesh.normals.insert(mesh.normals.end(), {n, n, n});
  mesh.triangles.push_back({base, base + 1, base + 2});
}

// One loop of plane (n; in-plane basis b1, b2) by ear clipping, triangles facing n; a fan
// from the centroid when no ear is found.
void triangulateCapLoop(const std::vector<Vector3d>& loop, const Vector3d& n, const Vector3d& b1, const Vector3d& b2,
                        TriangleMesh3& mesh) {
  std::vector<Vector2d> pts;
  for (const auto& p : loop) pts.emplace_back(p.dot(b1), p.dot(b2));
  double area = 0;
  for (std::size_t i = 0; i < pts.size(); ++i) {
    const Vector2d& a = pts[i];
    const Vector2d& b = pts[(i + 1) % pts.size()];
    area += a.x() * b.y() - a.y() * b.x();
  }
  std::vector<std::array<int, 3>> tris;
  std::vector<Vector2d> ccw = pts;
  const bool reversed = area < 0;
  if (reversed) std::reverse(ccw.begin(), ccw.end());
  const int N = int(pts.size());
  auto orig = [&](int i) { return reversed ? N - 1 - i : i; };
  if (!earClip(ccw, tris)) {  // fall back to a fan from the centroid
    Vector3d m = Vector3d::Zero();
    for (const auto& p : loop) m += p;
    m /= double(loop.size());
    for (int i = 0; i < N; ++i) appendCapTriangle(m, loop[std::size_t(i)], loop[std::size_t((i + 1) % N)], n, mesh);
    return;
  }
  for (const auto& t : tris) {
    const Vector3d& a = loop[std::size_t(orig(t[0]))];
    const Vector3d& b = loop[std::size_t(orig(t[1]))];
    const Vector3d& c = loop[std::size_t(orig(t[2]))];
    Vector3d fn = (b - a).cross(c - a);
    if (!(fn.norm() > 0)) continue;
    if (fn.dot(n) >= 0) appendCapTriangle(a, b, c, n, mesh);
    else appendCapTriangle(a, c, b, n, mesh);
  }
}

// A face of the region that the surface does not cross and that lies inside the solid (a
// slab's bottom, the end of a hyperbolic cylinder's box): the whole face, its corners in
// order around their centroid (a face of a convex polyhedron is convex), or nothing when a
// corner on the plane is outside the solid. Corners closer than a rounding tolerance (a
// vertex where more than three planes meet, found once per triple) count once.
std::vector<Vector3d> wholeFace(const HalfSpace& h, const CapCorners& inside, const std::vector<Vector3d>& polytope,
                                const Vector3d& b1, const Vector3d& b2) {
  std::size_t onPlane = 0;
  for (const auto& v : polytope) {
    const double mag = h.p.head<3>().cwiseAbs().dot(v.cwiseAbs()) + std::abs(h.p[3]);
    if (std::abs(h.eval(v)) <= 1e-9 * mag) ++onPlane;
  }
  if (inside.points.size() < 3 || inside.points.size() != onPlane) return {};
  Eigen::AlignedBox3d box;
  for (const auto& v : inside.points) box.extend(v);
  const double tol = 1e-9 * (box.sizes().norm() + box.max().cwiseAbs().maxCoeff());
  std::vector<Vector3d> face;
  for (const auto& v : inside.points) {
    bool seen = false;
    for (const auto& w : face) seen = seen || (v - w).norm() <= tol;
    if (!seen) face.push_back(v);
  }
  if (face.size() < 3) return {};
  Vector3d m = Vector3d::Zero();
  for (const auto& v : face) m += v;
  m /= double(face.size());
  std::sort(face.begin(), face.end(), [&](const Vector3d& a, const Vector3d& b) {
    return std::atan2((a - m).dot(b2), (a - m).dot(b1)) < std::atan2((b - m).dot(b2), (b - m).dot(b1));
  });
  return face;
}

}  // namespace

void buildCap(std::size_t k, const std::vector<CapSegment>& segs, const std::vector<HalfSpace>& planes,
              const std::vector<Vector3d>& polytope, const Quadric& q, TriangleMesh3& mesh) {
  const unsigned kbit = k < 32 ? (1u << k) : 0u;
  const CapCorners corners = capCorners(kbit, planes, polytope, q);
  const Vector3d n = planes[k].p.head<3>().normalized();
  const Vector3d b1 = (std::abs(n.x()) < 0.9 ? Vector3d::UnitX() : Vector3d::UnitY()).cross(n).normalized();
  const Vector3d b2 = n.cross(b1);
  if (segs.empty() && kbit) {
    const std::vector<Vector3d> face = wholeFace(planes[k], corners, polytope, b1, b2);
    if (!face.empty()) triangulateCapLoop(face, n, b1, b2, mesh);
    return;
  }
  if (segs.empty()) return;  // a face outside the solid
  for (const auto& loop : capLoops(capChains(segs), segs, corners, planes, kbit, n))
    triangulateCapLoop(loop, n, b1, b2, mesh);
}

}  // namespace qacc::tess
