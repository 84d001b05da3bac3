#include "modeling/tessellation/tessellation.h"

#include <algorithm>
#include <cmath>
#include <functional>
#include <map>
#include <stdexcept>
#include <unordered_map>

#include "modeling/geometry/primitive_bounds.h"
#include "modeling/geometry/quadric_type.h"

namespace qacc {

using Eigen::Vector2d;

void TriangleMesh3::append(const TriangleMesh3& o) {
  const int base = int(positions.size());
  positions.insert(positions.end(), o.positions.begin(), o.positions.end());
  normals.insert(normals.end(), o.normals.begin(), o.normals.end());
  for (const auto& t : o.triangles) triangles.push_back({t[0] + base, t[1] + base, t[2] + base});
  object.insert(object.end(), o.object.begin(), o.object.end());
  material.insert(material.end(), o.material.begin(), o.material.end());
  primitive.insert(primitive.end(), o.primitive.begin(), o.primitive.end());
}

const char* tessellationMethodName(TessellationMethod m) {
  switch (m) {
    case TessellationMethod::Parametric: return "parametric";
    case TessellationMethod::Planar: return "planar";
    case TessellationMethod::MarchingTetrahedra: return "marching-tetrahedra";
    case TessellationMethod::Empty: return "empty";
  }
  return "?";
}

std::vector<HalfSpace> frustumHalfSpaces(const Camera& camera, double aspect) {
  const Matrix4d M = camera.projection(aspect) * camera.view();
  std::vector<HalfSpace> out;
  // Sides slightly widened so that geometry reaching the image border is kept whole.
  const double side = 1.05;
  for (int r = 0; r < 2; ++r) {
    out.emplace_back(Vector4d(M.row(r).transpose() - side * M.row(3).transpose()));
    out.emplace_back(Vector4d(-M.row(r).transpose() - side * M.row(3).transpose()));
  }
  out.emplace_back(Vector4d(M.row(2).transpose() - M.row(3).transpose()));
  out.emplace_back(Vector4d(-M.row(2).transpose() - M.row(3).transpose()));
  return out;
}

double distanceToQuadric(const Quadric& quadric, const Vector3d& p) {
  const Quadric q = quadric.normalized();
  Vector3d x = p;
  for (int it = 0; it < 30; ++it) {
    const double f = q.eval(x);
    const Vector3d g = q.gradient(x);
    const double g2 = g.squaredNorm();
    if (!(g2 > 1e-300)) break;
    const Vector3d step = f * g / g2;
    x -= step;
    if (step.norm() <= 1e-14 * (1.0 + x.norm())) break;
  }
  return (x - p).norm();
}

namespace {

constexpr double kTwoPi = 2.0 * M_PI;

// ---------------------------------------------------------------------------------------
// Polygon clipping with plane tags. A vertex carries its domain coordinate (parameters
// (u, v, 0) or a 3-D point) and a bit mask of the clip planes it lies on.
struct ClipVertex {
  Vector3d coord;
  unsigned tags = 0;
};
using Polygon = std::vector<ClipVertex>;

bool lexLess(const Vector3d& a, const Vector3d& b) {
  if (a.x() != b.x()) return a.x() < b.x();
  if (a.y() != b.y()) return a.y() < b.y();
  return a.z() < b.z();
}

// A surface domain: coordinate → world position, and the cut of a domain segment by a plane.
struct Domain {
  std::function<Vector3d(const Vector3d&)> position;
  bool linear = false;  // position() is affine: cut exactly, no bisection

  Vector3d cut(Vector3d a, Vector3d b, const HalfSpace& h) const {
    if (lexLess(b, a)) std::swap(a, b);  // the same edge always gives the same point
    const double ga = h.eval(position(a)), gb = h.eval(position(b));
    if (linear) {
      const double t = ga / (ga - gb);
      return a + std::clamp(t, 0.0, 1.0) * (b - a);
    }
    const bool ka = h.keeps(ga);
    double lo = 0, hi = 1;
    for (int it = 0; it < 52; ++it) {
      const double mid = 0.5 * (lo + hi);
      const bool km = h.keeps(h.eval(position(a + mid * (b - a))));
      if (km == ka) lo = mid; else hi = mid;
    }
    return a + (0.5 * (lo + hi)) * (b - a);
  }

  // Parameters near x where the surface meets both planes (Newton with a numerical
  // Jacobian; x is returned unchanged when it does not converge).
  Vector3d corner(const Vector3d& x0, const HalfSpace& h1, const HalfSpace& h2) const {
    auto F = [&](const Vector3d& x) {
      const Vector3d p = position(x);
      return Vector2d(h1.eval(p) / h1.p.head<3>().norm(), h2.eval(p) / h2.p.head<3>().norm());
    };
    Vector3d x = x0;
    Vector2d r = F(x);
    const double r0 = r.norm();
    for (int it = 0; it < 12 && r.norm() > 1e-14 * (1 + position(x).norm()); ++it) {
      const double e = 1e-7 * (1 + x.head<2>().cwiseAbs().maxCoeff());
      Eigen::Matrix2d Jm;
      Jm.col(0) = (F(x + Vector3d(e, 0, 0)) - F(x - Vector3d(e, 0, 0))) / (2 * e);
      Jm.col(1) = (F(x + Vector3d(0, e, 0)) - F(x - Vector3d(0, e, 0))) / (2 * e);
      if (!(std::abs(Jm.determinant()) > 0)) break;
      const Vector2d step = Jm.partialPivLu().solve(r);
      x -= Vector3d(step.x(), step.y(), 0);
      r = F(x);
    }
    return (r.allFinite() && r.norm() < r0 && (x - x0).norm() < 0.5) ? x : x0;
  }
};

Polygon clipPolygon(const Polygon& in, const Domain& d, const std::vector<HalfSpace>& planes) {
  Polygon poly = in;
  for (std::size_t k = 0; k < planes.size() && !poly.empty(); ++k) {
    const unsigned bit = k < 32 ? (1u << k) : 0u;
    std::vector<char> kept(poly.size());
    bool all = true, none = true;
    for (std::size_t i = 0; i < poly.size(); ++i) {
      kept[i] = (poly[i].tags & bit) ? 1 : char(planes[k].keeps(planes[k].eval(d.position(poly[i].coord))));
      all = all && kept[i];
      none = none && !kept[i];
    }
    if (all) continue;
    if (none) return {};
    Polygon out;
    for (std::size_t i = 0; i < poly.size(); ++i) {
      const std::size_t j = (i + 1) % poly.size();
      if (kept[i]) out.push_back(poly[i]);
      if (kept[i] != kept[j]) {
        ClipVertex v;
        v.coord = d.cut(poly[i].coord, poly[j].coord, planes[k]);
        v.tags = (poly[i].tags & poly[j].tags) | bit;
        if (!d.linear && (v.tags & ~bit)) {  // a corner: on the surface and on two planes
          for (std::size_t m = 0; m < planes.size() && m < 32; ++m)
            if (m != k && (v.tags & (1u << m))) {
              v.coord = d.corner(v.coord, planes[m], planes[k]);
              break;
            }
        }
        out.push_back(v);
      }
    }
    poly.swap(out);
  }
  return poly.size() >= 3 ? poly : Polygon{};
}

// Cap segments per clip plane: world positions of polygon edges lying on that plane.
// A boundary segment of a cap, oriented so that the cap lies on its left seen from
// outside the solid, with the clip-plane tags of its end points.
struct CapSegment {
  Vector3d a, b;
  unsigned ta = 0, tb = 0;
};
struct CapSegments {
  std::vector<std::vector<CapSegment>> per_plane;
};

// Builder of one primitive's surface triangles (triangle soup, one normal per corner).
struct SurfaceBuilder {
  const Quadric& q;  // normalised
  const Domain& domain;
  const std::vector<HalfSpace>& planes;
  std::size_t cap_planes;  // planes [0, cap_planes) get caps (the primitive's own clip planes)
  TriangleMesh3& mesh;
  CapSegments& caps;

  Vector3d normalAt(const Vector3d& coord, const Vector3d& towards) const {
    const Vector3d p = domain.position(coord);
    Vector3d g = q.gradient(p);
    const double scale = 1.0 + p.norm();
    if (!(g.norm() > 1e-9 * scale)) {  // singular point (cone apex): step into the triangle
      g = q.gradient(domain.position(coord + 1e-4 * (towards - coord)));
    }
    const double n = g.norm();
    return n > 0 ? Vector3d(g / n) : Vector3d(0, 0, 1);
  }

  void emit(const ClipVertex& a, const ClipVertex& b, const ClipVertex& c) {
    const Vector3d pa = domain.position(a.coord), pb = domain.position(b.coord), pc = domain.position(c.coord);
    if (pa == pb || pb == pc || pa == pc) return;
    const Vector3d fn = (pb - pa).cross(pc - pa);
    if (!(fn.norm() > 0)) return;
    const Vector3d centre = (a.coord + b.coord + c.coord) / 3.0;
    Vector3d na = normalAt(a.coord, centre), nb = normalAt(b.coord, centre), nc = normalAt(c.coord, centre);
    const int base = int(mesh.positions.size());
    if (fn.dot(na + nb + nc) >= 0) {
      mesh.positions.insert(mesh.positions.end(), {pa, pb, pc});
      mesh.normals.insert(mesh.normals.end(), {na, nb, nc});
    } else {
      mesh.positions.insert(mesh.positions.end(), {pa, pc, pb});
      mesh.normals.insert(mesh.normals.end(), {na, nc, nb});
    }
    mesh.triangles.push_back({base, base + 1, base + 2});
  }

  unsigned onPlanes(const Vector3d& coord) const {  // grid vertices that lie on clip planes
    const Vector3d p = domain.position(coord);
    unsigned t = 0;
    for (std::size_t k = 0; k < planes.size() && k < 32; ++k) {
      const double g = planes[k].eval(p);
      if (std::abs(g) <= 1e-11 * (planes[k].p.head<3>().norm() * p.norm() + std::abs(planes[k].p[3]) + 1e-300))
        t |= 1u << k;
    }
    return t;
  }

  void addTriangle(const Vector3d& a, const Vector3d& b, const Vector3d& c) { addPolygon({a, b, c}); }

  // A convex domain polygon, clipped as a whole then fanned.
  void addPolygon(const std::vector<Vector3d>& corners) {
    Polygon in;
    for (const auto& x : corners) in.push_back({x, onPlanes(x)});
    const Polygon poly = clipPolygon(in, domain, planes);
    if (poly.empty()) return;
    for (std::size_t i = 1; i + 1 < poly.size(); ++i) emit(poly[0], poly[i], poly[i + 1]);
    if (cap_planes == 0) return;
    // Orientation of the polygon against the outward normal (Newell normal vs gradient).
    Vector3d newell = Vector3d::Zero(), grad = Vector3d::Zero();
    std::vector<Vector3d> P(poly.size());
    for (std::size_t i = 0; i < poly.size(); ++i) P[i] = domain.position(poly[i].coord);
    for (std::size_t i = 0; i < poly.size(); ++i) {
      newell += P[i].cross(P[(i + 1) % poly.size()]);
      grad += q.gradient(P[i]);
    }
    const bool outward = newell.dot(grad) >= 0;
    for (std::size_t i = 0; i < poly.size(); ++i) {
      const std::size_t j = (i + 1) % poly.size();
      const unsigned common = poly[i].tags & poly[j].tags;
      if (!common || (common & (common - 1))) continue;  // on no plane, or along a plane-plane line
      if (P[i] == P[j]) continue;
      for (std::size_t k = 0; k < cap_planes && k < 32; ++k) {
        if (common != (1u << k)) continue;
        // The cap runs the shared edge the other way round.
        if (outward) caps.per_plane[k].push_back({P[j], P[i], poly[j].tags, poly[i].tags});
        else caps.per_plane[k].push_back({P[i], P[j], poly[i].tags, poly[j].tags});
      }
    }
  }

  void addQuad(const Vector3d& a, const Vector3d& b, const Vector3d& c, const Vector3d& d) {
    addTriangle(a, b, c);
    addTriangle(a, c, d);
  }
};

struct PointKey {
  bool operator()(const Vector3d& a, const Vector3d& b) const { return lexLess(a, b); }
};

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

// Cap on plane h from its oriented boundary segments: chains are followed end to start;
// an open chain (cut by another clip plane j) is closed along the line h ∩ j to the next
// chain start on that line; each loop is triangulated by ear clipping in the plane.
void buildCap(std::size_t k, const std::vector<CapSegment>& segs, const std::vector<HalfSpace>& planes,
              const std::vector<Vector3d>& polytope, const Quadric& q, TriangleMesh3& mesh) {
  const HalfSpace& h = planes[k];
  const unsigned kbit = k < 32 ? (1u << k) : 0u;
  // Corners of the cap's polygon: polytope vertices on this plane, with their plane tags.
  std::vector<Vector3d> corners;
  std::vector<unsigned> cornerTags;
  for (const auto& v : polytope) {
    unsigned t = 0;
    for (std::size_t m = 0; m < planes.size() && m < 32; ++m) {
      const double mag = planes[m].p.head<3>().cwiseAbs().dot(v.cwiseAbs()) + std::abs(planes[m].p[3]);
      if (std::abs(planes[m].eval(v)) <= 1e-9 * mag) t |= 1u << m;
    }
    // Only corners inside the solid (f <= 0) bound the cap.
    if ((t & kbit) && q.eval(v) <= 1e-9 * (1 + v.squaredNorm())) {
      corners.push_back(v);
      cornerTags.push_back(t);
    }
  }
  if (segs.size() < 2) return;
  const Vector3d n = h.p.head<3>().normalized();
  const Vector3d b1 = (std::abs(n.x()) < 0.9 ? Vector3d::UnitX() : Vector3d::UnitY()).cross(n).normalized();
  const Vector3d b2 = n.cross(b1);
  std::map<Vector3d, std::size_t, PointKey> startAt;  // segment starting at a point
  for (std::size_t i = 0; i < segs.size(); ++i) startAt.emplace(segs[i].a, i);
  std::map<Vector3d, int, PointKey> endCount;
  for (const auto& sg : segs) endCount[sg.b]++;
  std::vector<char> used(segs.size(), 0);
  // Chains: start at segments whose start is no segment's end (open chains) first.
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
  // Join open chains into loops.
  std::vector<char> chainUsed(chains.size(), 0);
  std::vector<std::vector<Vector3d>> loops;
  for (std::size_t c0 = 0; c0 < chains.size(); ++c0) {
    if (chainUsed[c0]) continue;
    std::vector<Vector3d> loop;
    std::size_t c = c0;
    for (int guard = 0; guard <= int(chains.size()); ++guard) {
      chainUsed[c] = 1;
      for (std::size_t si : chains[c]) loop.push_back(segs[si].a);
      const CapSegment& last = segs[chains[c].back()];
      if (last.b == segs[chains[c0].front()].a) break;  // closed
      // Open: walk along the boundary of the cap's polygon (plane h ∩ the other clip
      // half-spaces) with the interior on the left: along the line h ∩ j to the nearest chain
      // start on it, turning at the polygon's corners.
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
        for (std::size_t v = 0; v < corners.size(); ++v) {
          if (!(cornerTags[v] & (1u << j))) continue;
          const double along = (corners[v] - e).dot(dir);
          if (along > eps && along < best) {
            best = along;
            bestChain = -1;
            bestCorner = int(v);
          }
        }
        if (bestChain >= 0) {
          pick = std::size_t(bestChain);
        } else if (bestCorner >= 0) {
          e = corners[std::size_t(bestCorner)];
          loop.push_back(e);
          etags = cornerTags[std::size_t(bestCorner)] & ~kbit & ~(1u << j);
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
      if (pick == c0 || pick == chains.size()) break;
      c = pick;
    }
    // Remove consecutive duplicates.
    std::vector<Vector3d> clean;
    for (const auto& p : loop)
      if (clean.empty() || !(clean.back() == p)) clean.push_back(p);
    while (clean.size() > 1 && clean.front() == clean.back()) clean.pop_back();
    if (clean.size() >= 3) loops.push_back(clean);
  }
  for (const auto& loop : loops) {
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
      tris.clear();
      Vector3d m = Vector3d::Zero();
      for (const auto& p : loop) m += p;
      m /= double(loop.size());
      for (int i = 0; i < N; ++i) {
        const Vector3d& a = loop[std::size_t(i)];
        const Vector3d& b = loop[std::size_t((i + 1) % N)];
        const int base = int(mesh.positions.size());
        mesh.positions.insert(mesh.positions.end(), {m, a, b});
        mesh.normals.insert(mesh.normals.end(), {n, n, n});
        mesh.triangles.push_back({base, base + 1, base + 2});
      }
      continue;
    }
    for (const auto& t : tris) {
      const Vector3d& a = loop[std::size_t(orig(t[0]))];
      const Vector3d& b = loop[std::size_t(orig(t[1]))];
      const Vector3d& c = loop[std::size_t(orig(t[2]))];
      Vector3d fn = (b - a).cross(c - a);
      if (!(fn.norm() > 0)) continue;
      const int base = int(mesh.positions.size());
      if (fn.dot(n) >= 0) mesh.positions.insert(mesh.positions.end(), {a, b, c});
      else mesh.positions.insert(mesh.positions.end(), {a, c, b});
      mesh.normals.insert(mesh.normals.end(), {n, n, n});
      mesh.triangles.push_back({base, base + 1, base + 2});
    }
  }
}

// Canonical frame of a quadric: eigenvectors of the quadratic part (sorted so that the
// axis is the last column), sign normalised so that at least as many eigenvalues are
// positive as negative.
struct Frame {
  Matrix3d E;
  Vector3d g;
  double J = 0;
  Eigen::Vector3d lambda;
  Matrix3d V;
};

Frame canonicalFrame(const Quadric& q) {
  Frame f;
  Matrix4d Q = q.normalized().Q;
  Eigen::SelfAdjointEigenSolver<Matrix3d> es(Q.topLeftCorner<3, 3>());
  int pos = 0, neg = 0;
  const double tol = 1e-9 * es.eigenvalues().cwiseAbs().maxCoeff();
  for (int i = 0; i < 3; ++i) {
    if (es.eigenvalues()[i] > tol) ++pos;
    if (es.eigenvalues()[i] < -tol) ++neg;
  }
  if (neg > pos) Q = -Q;
  f.E = Q.topLeftCorner<3, 3>();
  f.g = Q.topRightCorner<3, 1>();
  f.J = Q(3, 3);
  Eigen::SelfAdjointEigenSolver<Matrix3d> es2(f.E);
  f.lambda = es2.eigenvalues();
  f.V = es2.eigenvectors();
  return f;
}

// Reorder the frame's columns so that column 2 is the eigenvector `axis`.
void putAxisLast(Frame& f, int axis) {
  if (axis == 2) return;
  std::swap(f.lambda[axis], f.lambda[2]);
  f.V.col(axis).swap(f.V.col(2));
}

// Centre in the span of the non-zero eigenvalues: c = −Σ (vᵢ·g / λᵢ) vᵢ.
Vector3d partialCentre(const Frame& f, double tol) {
  Vector3d c = Vector3d::Zero();
  for (int i = 0; i < 3; ++i)
    if (std::abs(f.lambda[i]) > tol) c -= (f.V.col(i).dot(f.g) / f.lambda[i]) * f.V.col(i);
  return c;
}

double evalFrame(const Frame& f, const Vector3d& x) { return x.dot(f.E * x) + 2 * f.g.dot(x) + f.J; }

struct Grid {
  int nu = 3, nv = 1;
};

// Grid sizes for a target triangle count.
Grid gridFor(QuadricType type, int target) {
  const int N = std::max(2, target);
  Grid g;
  switch (type) {
    case QuadricType::Ellipsoid: {
      g.nv = std::max(2, int(std::lround(std::sqrt(N / 4.0) + 0.5)));
      g.nu = std::max(3, N / (2 * (g.nv - 1)));
      break;
    }
    case QuadricType::EllipticCylinder:
      g.nv = 1;
      g.nu = std::max(3, N / 2);
      break;
    case QuadricType::EllipticCone:
      g.nv = 1;
      g.nu = std::max(3, N);
      break;
    case QuadricType::EllipticParaboloid:
    case QuadricType::HyperboloidTwoSheets:
      g.nv = std::max(1, int(std::lround(std::sqrt(N / 4.0))));
      g.nu = std::max(3, N / std::max(1, 2 * g.nv - 1));
      break;
    default:
      g.nv = std::max(1, int(std::lround(std::sqrt(N / 4.0))));
      g.nu = std::max(3, N / (2 * g.nv));
      break;
  }
  return g;
}

// Parametric grid over [u0,u1] x [v0,v1] (u periodic) through the builder.
void emitGrid(SurfaceBuilder& sb, const Grid& g, double v0, double v1, const std::vector<double>& extra_v = {}) {
  std::vector<double> vs;
  for (int j = 0; j <= g.nv; ++j) vs.push_back(v0 + (v1 - v0) * j / g.nv);
  const double snap = 1e-9 * (std::abs(v1 - v0) + std::abs(v0) + std::abs(v1));
  for (double e : extra_v) {
    for (double& v : vs)
      if (std::abs(v - e) <= snap) v = e;
    if (e > v0 && e < v1) vs.push_back(e);
  }
  std::sort(vs.begin(), vs.end());
  vs.erase(std::unique(vs.begin(), vs.end()), vs.end());
  for (std::size_t j = 0; j + 1 < vs.size(); ++j)
    for (int i = 0; i < g.nu; ++i) {
      const double ua = kTwoPi * i / g.nu, ub = (i + 1 == g.nu) ? kTwoPi : kTwoPi * (i + 1) / g.nu;
      sb.addQuad(Vector3d(ua, vs[j], 0), Vector3d(ub, vs[j], 0), Vector3d(ub, vs[j + 1], 0), Vector3d(ua, vs[j + 1], 0));
    }
}

double wrapU(double u) { return u >= kTwoPi ? u - kTwoPi : u; }

// The part of `box` where the surface can be: the cells of a 40³ scan whose corners change
// sign (or come within a cell's gradient bound of zero), inside the clip planes' reach.
Eigen::AlignedBox3d surfaceBox(const Quadric& q, const Eigen::AlignedBox3d& box, const std::vector<HalfSpace>& planes) {
  const int n = 40;
  const Vector3d h = box.sizes() / n;
  Eigen::AlignedBox3d out;
  std::vector<double> val(std::size_t(n + 1) * (n + 1) * (n + 1));
  auto at = [&](int i, int j, int k) -> double& { return val[(std::size_t(k) * (n + 1) + j) * (n + 1) + i]; };
  auto pt = [&](int i, int j, int k) { return Vector3d(box.min() + h.cwiseProduct(Vector3d(i, j, k))); };
  for (int k = 0; k <= n; ++k)
    for (int j = 0; j <= n; ++j)
      for (int i = 0; i <= n; ++i) at(i, j, k) = q.eval(pt(i, j, k));
  for (int k = 0; k < n; ++k)
    for (int j = 0; j < n; ++j)
      for (int i = 0; i < n; ++i) {
        double lo = 1e300, hi = -1e300;
        for (int c = 0; c < 8; ++c) {
          const double v = at(i + (c & 1), j + ((c >> 1) & 1), k + ((c >> 2) & 1));
          lo = std::min(lo, v);
          hi = std::max(hi, v);
        }
        // A quadric can dip between corners: allow a margin of one cell's curvature.
        const Vector3d centre = pt(i, j, k) + 0.5 * h;
        const double margin = 2.0 * (q.Q.topLeftCorner<3, 3>().cwiseAbs() * h.cwiseAbs()).dot(h.cwiseAbs());
        if (lo > margin || hi < -margin) continue;
        bool inside = true;
        for (const auto& pl : planes)
          if (pl.eval(centre) > 0.5 * pl.p.head<3>().cwiseAbs().dot(h) + 1e-12) inside = false;
        if (!inside) continue;
        out.extend(pt(i, j, k));
        out.extend(pt(i + 1, j + 1, k + 1));
      }
  return out.isEmpty() ? box : out;
}

// Marching tetrahedra over `box` with about n cells along the longest side.
void marchingTetrahedra(SurfaceBuilder& sb, const Quadric& q, const Eigen::AlignedBox3d& box0, int n) {
  Eigen::AlignedBox3d box = box0;
  const Vector3d pad = 1e-3 * box.sizes() + Vector3d::Constant(1e-9);
  box.extend(box.max() + pad);
  box.extend(box.min() - pad);
  const double h = box.sizes().maxCoeff() / n;
  int dims[3];
  for (int a = 0; a < 3; ++a) dims[a] = std::max(1, int(std::ceil(box.sizes()[a] / h - 1e-9)));
  auto point = [&](int i, int j, int k) { return Vector3d(box.min() + h * Vector3d(i, j, k)); };
  auto idx = [&](int i, int j, int k) {
    return (std::int64_t(k) * (dims[1] + 1) + j) * (dims[0] + 1) + i;
  };
  std::vector<double> val(std::size_t((dims[0] + 1)) * (dims[1] + 1) * (dims[2] + 1));
  for (int k = 0; k <= dims[2]; ++k)
    for (int j = 0; j <= dims[1]; ++j)
      for (int i = 0; i <= dims[0]; ++i) {
        double v = q.eval(point(i, j, k));
        if (v == 0) v = 1e-300;  // grid points never exactly on the surface
        val[std::size_t(idx(i, j, k))] = v;
      }
  std::unordered_map<std::uint64_t, Vector3d> edgeCache;
  const std::uint64_t npoints = val.size();
  auto edgePoint = [&](std::int64_t a, const Vector3d& pa, std::int64_t b, const Vector3d& pb) {
    if (b < a) return Vector3d();  // never: callers order
    const std::uint64_t key = std::uint64_t(a) * npoints + std::uint64_t(b);  // exact pair key
    auto it = edgeCache.find(key);
    if (it != edgeCache.end()) return it->second;
    const double fa = val[std::size_t(a)], fb = val[std::size_t(b)];
    Vector3d x = pa + (fa / (fa - fb)) * (pb - pa);
    for (int s = 0; s < 3; ++s) {  // Newton along the gradient, kept on the edge's scale
      const Vector3d g = q.gradient(x);
      const double g2 = g.squaredNorm();
      if (!(g2 > 0)) break;
      Vector3d step = q.eval(x) * g / g2;
      if (step.norm() > h) break;
      x -= step;
    }
    edgeCache.emplace(key, x);
    return x;
  };
  static const int perms[6][3] = {{0, 1, 2}, {0, 2, 1}, {1, 0, 2}, {1, 2, 0}, {2, 0, 1}, {2, 1, 0}};
  for (int k = 0; k < dims[2]; ++k)
    for (int j = 0; j < dims[1]; ++j)
      for (int i = 0; i < dims[0]; ++i) {
        for (const auto& p : perms) {
          int c[4][3];
          c[0][0] = i; c[0][1] = j; c[0][2] = k;
          for (int s = 1; s < 4; ++s) {
            for (int a = 0; a < 3; ++a) c[s][a] = c[s - 1][a];
            c[s][p[s - 1]] += 1;
          }
          std::int64_t id[4];
          Vector3d P[4];
          bool in[4];
          int nin = 0;
          for (int s = 0; s < 4; ++s) {
            id[s] = idx(c[s][0], c[s][1], c[s][2]);
            P[s] = point(c[s][0], c[s][1], c[s][2]);
            in[s] = val[std::size_t(id[s])] < 0;
            nin += in[s];
          }
          if (nin == 0 || nin == 4) continue;
          auto E = [&](int a, int b) {
            return id[a] < id[b] ? edgePoint(id[a], P[a], id[b], P[b]) : edgePoint(id[b], P[b], id[a], P[a]);
          };
          if (nin == 1 || nin == 3) {
            int lone = 0;
            for (int s = 0; s < 4; ++s)
              if (in[s] == (nin == 1)) lone = s;
            int o[3], m = 0;
            for (int s = 0; s < 4; ++s)
              if (s != lone) o[m++] = s;
            sb.addTriangle(E(lone, o[0]), E(lone, o[1]), E(lone, o[2]));
          } else {
            int a[2], b[2], na = 0, nb = 0;
            for (int s = 0; s < 4; ++s) (in[s] ? a[na++] : b[nb++]) = s;
            sb.addQuad(E(a[0], b[0]), E(a[0], b[1]), E(a[1], b[1]), E(a[1], b[0]));
          }
        }
      }
}

constexpr double kFar = 1e12;  // a box this large stands for "unbounded"

// Vertices of the polyhedron ∩ [−kFar, kFar]³ (exact enumeration of plane triples).
std::vector<Vector3d> polytopeVertices(const std::vector<HalfSpace>& planes, double far = kFar) {
  std::vector<Vector4d> P;
  for (const auto& h : planes) P.push_back(h.p);
  for (int a = 0; a < 3; ++a)
    for (double s : {-1.0, 1.0}) {
      Vector4d p = Vector4d::Zero();
      p[a] = s;
      p[3] = -far;
      P.push_back(p);
    }
  std::vector<Vector3d> out;
  const std::size_t n = P.size();
  for (std::size_t i = 0; i < n; ++i)
    for (std::size_t j = i + 1; j < n; ++j)
      for (std::size_t k = j + 1; k < n; ++k) {
        Matrix3d A;
        A << P[i].head<3>().transpose(), P[j].head<3>().transpose(), P[k].head<3>().transpose();
        const double scale = P[i].head<3>().norm() * P[j].head<3>().norm() * P[k].head<3>().norm();
        if (!(std::abs(A.determinant()) > 1e-12 * scale)) continue;
        const Vector3d v = A.inverse() * Vector3d(-P[i][3], -P[j][3], -P[k][3]);
        bool ok = v.allFinite();
        for (std::size_t m = 0; ok && m < n; ++m) {
          const double mag = P[m].head<3>().cwiseAbs().dot(v.cwiseAbs()) + std::abs(P[m][3]);
          if (P[m].dot(v.homogeneous()) > 1e-9 * mag) ok = false;
        }
        if (ok) out.push_back(v);
      }
  return out;
}

bool finiteExtent(const std::vector<Vector3d>& verts) {
  if (verts.empty()) return false;
  for (const auto& v : verts)
    if (v.cwiseAbs().maxCoeff() > 0.5 * kFar) return false;
  return true;
}

// Axial extent [tmin, tmax] of the polyhedron's vertices along unit axis e from c.
void axialExtent(const std::vector<Vector3d>& verts, const Vector3d& c, const Vector3d& e, double& tmin, double& tmax) {
  tmin = 1e300;
  tmax = -1e300;
  for (const auto& v : verts) {
    const double t = e.dot(v - c);
    tmin = std::min(tmin, t);
    tmax = std::max(tmax, t);
  }
}

PrimitiveTessellation tessellateOnce(const Primitive& prim, int target, const Camera* camera, double aspect,
                                     int chordSamples, bool forceMarching = false) {
  PrimitiveTessellation out;
  const Quadric q = prim.quadric.normalized();
  const std::size_t own = prim.clip.size();
  // QuadricType::All has no parametric branch: it selects marching tetrahedra over the region.
  const QuadricType type = forceMarching ? QuadricType::All
                                         : (prim.isPlanar() ? QuadricType::Plane : quadricType(prim.quadric));
  Frame f = canonicalFrame(prim.quadric);
  const double ltol = 1e-9 * f.lambda.cwiseAbs().maxCoeff();
  auto indexOfSign = [&](int sign) {  // index of the eigenvalue with this sign (0 = zero)
    for (int i = 0; i < 3; ++i) {
      const int s = f.lambda[i] > ltol ? 1 : (f.lambda[i] < -ltol ? -1 : 0);
      if (s == sign) return i;
    }
    return -1;
  };
  switch (type) {  // the axis of the axial types is the last column of the frame
    case QuadricType::EllipticCylinder:
    case QuadricType::EllipticParaboloid: putAxisLast(f, indexOfSign(0)); break;
    case QuadricType::EllipticCone:
    case QuadricType::HyperboloidOneSheet:
    case QuadricType::HyperboloidTwoSheets: putAxisLast(f, indexOfSign(-1)); break;
    default: break;
  }
  const bool axial = type == QuadricType::EllipticCylinder || type == QuadricType::EllipticParaboloid ||
                     type == QuadricType::EllipticCone || type == QuadricType::HyperboloidOneSheet ||
                     type == QuadricType::HyperboloidTwoSheets;

  // The region to tessellate: the clip polyhedron, limited to the view frustum when it does
  // not bound the piece. Axial types need only the axial extent; planes their polygon.
  std::vector<HalfSpace> planes = prim.clip;
  auto regionVertices = [&](const std::vector<HalfSpace>& pl, double far = kFar) {
    std::vector<HalfSpace> ext = pl;
    if (type == QuadricType::Plane) {
      const Vector4d pp = q.Q.col(3) * 2.0;  // f = 2 g·x + J for a plane: (2g, J)
      Vector4d plane(pp.x(), pp.y(), pp.z(), q.Q(3, 3));
      ext.emplace_back(plane);
      ext.emplace_back(Vector4d(-plane));
    }
    return polytopeVertices(ext, far);
  };
  std::vector<HalfSpace> bounding;  // extra planes that only bound the region (not clipped)
  if (type == QuadricType::EllipticParaboloid) {
    // The surface lies on one side of its vertex's tangent plane: t <= tv when h > 0.
    const Vector3d c = partialCentre(f, ltol);
    const double h = f.V.col(2).dot(f.g);
    const double tv = -evalFrame(f, c) / (2 * h);
    const Vector3d e = (h > 0 ? 1.0 : -1.0) * f.V.col(2);
    bounding.push_back(HalfSpace::fromPointNormal(c + tv * f.V.col(2), e));
  }
  auto withBounding = [&](std::vector<HalfSpace> pl) {
    pl.insert(pl.end(), bounding.begin(), bounding.end());
    return pl;
  };
  std::vector<Vector3d> verts;
  bool bounded = true;
  if (type != QuadricType::Ellipsoid) {
    verts = regionVertices(withBounding(planes));
    if (axial) {
      double t0, t1;
      axialExtent(verts, Vector3d::Zero(), f.V.col(2), t0, t1);
      bounded = !verts.empty() && std::abs(t0) < 0.5 * kFar && std::abs(t1) < 0.5 * kFar;
    } else {
      bounded = finiteExtent(verts);
    }
    if (!bounded && camera && !verts.empty()) {
      for (const auto& h : frustumHalfSpaces(*camera, aspect)) planes.push_back(h);
      verts = regionVertices(withBounding(planes));
      bounded = finiteExtent(verts);
    }
    if (verts.empty() || !bounded) return out;  // nothing (bounded) to draw
    if (axial) {
      // Vertices on a 1e12 box carry ~1e-4 of rounding into the axial extent: enumerate
      // again in a box just large enough to hold the surface over that extent.
      const Vector3d c = partialCentre(f, ltol);
      double t0, t1;
      axialExtent(verts, c, f.V.col(2), t0, t1);
      const double T = std::max(std::abs(t0), std::abs(t1));
      const double lmin = std::min(std::abs(f.lambda[0]), std::abs(f.lambda[1]));
      const double R = std::sqrt((std::abs(evalFrame(f, c)) + std::abs(f.lambda[2]) * T * T +
                                  2 * std::abs(f.V.col(2).dot(f.g)) * T) / lmin);
      const double far = 4 * (1 + c.norm() + R + T);
      if (far < 0.5 * kFar) verts = regionVertices(withBounding(planes), far);
      if (verts.empty()) return out;
    }
  }
  Eigen::AlignedBox3d box;
  for (const auto& v : verts) box.extend(v);
  if (type == QuadricType::Ellipsoid) box = primitiveBounds(prim).box;
  const double diag = box.isEmpty() ? 1.0 : box.sizes().norm();

  CapSegments caps;
  caps.per_plane.resize(own);
  Domain domain;
  const std::size_t capPlanes = (prim.solid && !prim.isPlanar()) ? own : 0;
  SurfaceBuilder sb{q, domain, planes, capPlanes, out.mesh, caps};

  out.method = TessellationMethod::Parametric;
  switch (type) {
    case QuadricType::Ellipsoid: {
      const Vector3d c = -f.E.ldlt().solve(f.g);
      const double Jp = evalFrame(f, c);
      const Vector3d a(std::sqrt(-Jp / f.lambda[0]), std::sqrt(-Jp / f.lambda[1]), std::sqrt(-Jp / f.lambda[2]));
      const Matrix3d V = f.V;
      domain.position = [c, a, V](const Vector3d& uv) {
        const double u = wrapU(uv.x()), v = uv.y();
        const double sv = (v <= 0 || v >= M_PI) ? 0.0 : std::sin(v);
        const double cv = v <= 0 ? 1.0 : (v >= M_PI ? -1.0 : std::cos(v));
        return Vector3d(c + V * Vector3d(a.x() * sv * std::cos(u), a.y() * sv * std::sin(u), a.z() * cv));
      };
      emitGrid(sb, gridFor(type, target), 0.0, M_PI);
      break;
    }
    case QuadricType::EllipticCylinder: {
      const Vector3d c = partialCentre(f, ltol);
      const double Jp = evalFrame(f, c);
      const double a1 = std::sqrt(-Jp / f.lambda[0]), a2 = std::sqrt(-Jp / f.lambda[1]);
      const Matrix3d V = f.V;
      double t0, t1;
      axialExtent(verts, c, V.col(2), t0, t1);
      domain.position = [c, a1, a2, V](const Vector3d& uv) {
        const double u = wrapU(uv.x());
        return Vector3d(c + a1 * std::cos(u) * V.col(0) + a2 * std::sin(u) * V.col(1) + uv.y() * V.col(2));
      };
      emitGrid(sb, gridFor(type, target), t0, t1);
      break;
    }
    case QuadricType::EllipticCone:
    case QuadricType::HyperboloidOneSheet:
    case QuadricType::HyperboloidTwoSheets: {
      const Vector3d c = -f.E.ldlt().solve(f.g);
      const double Jp = type == QuadricType::EllipticCone ? 0.0 : evalFrame(f, c);
      const double l3 = -f.lambda[2];
      const double s1 = 1 / std::sqrt(f.lambda[0]), s2 = 1 / std::sqrt(f.lambda[1]);
      const Matrix3d V = f.V;
      double t0, t1;
      axialExtent(verts, c, V.col(2), t0, t1);
      if (type != QuadricType::HyperboloidTwoSheets) {
        domain.position = [c, Jp, l3, s1, s2, V](const Vector3d& uv) {
          const double u = wrapU(uv.x()), t = uv.y();
          const double r = std::sqrt(std::max(0.0, l3 * t * t - Jp));
          return Vector3d(c + r * (s1 * std::cos(u) * V.col(0) + s2 * std::sin(u) * V.col(1)) + t * V.col(2));
        };
        Grid g = gridFor(type, target);
        if (type == QuadricType::EllipticCone && t0 < 0 && t1 > 0) g.nu = std::max(3, g.nu / 2);
        emitGrid(sb, g, t0, t1, {0.0});
      } else {
        // Sheets t = ±t0 cosh s, radius √J' sinh s (s >= 0), one grid per sheet.
        const double tv = std::sqrt(Jp / l3), rj = std::sqrt(Jp);
        Grid g = gridFor(type, target);
        for (double sheet : {1.0, -1.0}) {
          const double reach = sheet > 0 ? t1 : -t0;
          if (reach <= tv) continue;
          const double smax = std::acosh(reach / tv);
          domain.position = [c, tv, rj, s1, s2, V, sheet](const Vector3d& uv) {
            const double u = wrapU(uv.x()), s = uv.y();
            const double r = s <= 0 ? 0.0 : rj * std::sinh(s);
            return Vector3d(c + r * (s1 * std::cos(u) * V.col(0) + s2 * std::sin(u) * V.col(1)) +
                            sheet * tv * std::cosh(s) * V.col(2));
          };
          emitGrid(sb, g, 0.0, smax);
        }
      }
      break;
    }
    case QuadricType::EllipticParaboloid: {
      const Vector3d c = partialCentre(f, ltol);
      const double h = f.V.col(2).dot(f.g);
      const double tv = -evalFrame(f, c) / (2 * h);
      const double s1 = 1 / std::sqrt(f.lambda[0]), s2 = 1 / std::sqrt(f.lambda[1]);
      const Matrix3d V = f.V;
      double t0, t1;
      axialExtent(verts, c, V.col(2), t0, t1);
      const double rho2 = std::max({0.0, 2 * h * (tv - t0), 2 * h * (tv - t1)});
      const double rmax = std::sqrt(rho2);
      domain.position = [c, h, tv, s1, s2, V](const Vector3d& uv) {
        const double u = wrapU(uv.x()), r = uv.y();
        return Vector3d(c + r * (s1 * std::cos(u) * V.col(0) + s2 * std::sin(u) * V.col(1)) +
                        (tv - r * r / (2 * h)) * V.col(2));
      };
      emitGrid(sb, gridFor(type, target), 0.0, rmax);
      break;
    }
    case QuadricType::Plane: {
      out.method = TessellationMethod::Planar;
      const Vector3d n = q.gradient(box.center());
      const double nn = n.norm();
      if (!(nn > 0)) return out;
      const Vector3d un = n / nn;
      const Vector3d o = box.center() - (q.eval(box.center()) / nn) * un;
      const Vector3d b1 = (std::abs(un.x()) < 0.9 ? Vector3d::UnitX() : Vector3d::UnitY()).cross(un).normalized();
      const Vector3d b2 = un.cross(b1);
      const double R = diag * 1.01 + 1e-9;
      domain.linear = true;
      domain.position = [o, b1, b2](const Vector3d& uv) { return Vector3d(o + uv.x() * b1 + uv.y() * b2); };
      sb.addPolygon({Vector3d(-R, -R, 0), Vector3d(R, -R, 0), Vector3d(R, R, 0), Vector3d(-R, R, 0)});
      break;
    }
    default: {
      out.method = TessellationMethod::MarchingTetrahedra;
      domain.linear = true;
      domain.position = [](const Vector3d& p) { return p; };
      const int n = std::max(4, int(std::lround(std::sqrt(std::max(2, target) / 3.0))));
      marchingTetrahedra(sb, q, surfaceBox(q, box, planes), n);
      break;
    }
  }
  out.surface_triangles = out.mesh.size();
  const std::vector<Vector3d> polyVerts = capPlanes ? polytopeVertices(planes) : std::vector<Vector3d>();
  for (std::size_t k = 0; k < capPlanes; ++k) buildCap(k, caps.per_plane[k], planes, polyVerts, q, out.mesh);
  out.cap_triangles = out.mesh.size() - out.surface_triangles;
  if (out.mesh.size() == 0) out.method = TessellationMethod::Empty;
  const ChordError ce = measureChordError(out.mesh, prim.quadric, 0, out.surface_triangles, chordSamples);
  out.max_chord_error = ce.max;
  out.mean_chord_error = ce.mean;
  return out;
}

}  // namespace

// A parametric grid spans the whole natural surface; a small clipped piece of a large
// surface (a Bernstein-Bézier cell far out on a hyperboloid sheet) can receive few or none
// of its triangles. When a clipped piece gets under a quarter of its target, marching
// tetrahedra over the piece's own region is tried and the denser mesh kept.
PrimitiveTessellation tessellateCovering(const Primitive& prim, int target, const Camera* camera, double aspect,
                                         int chordSamples) {
  PrimitiveTessellation t = tessellateOnce(prim, target, camera, aspect, chordSamples);
  const bool parametric = t.method == TessellationMethod::Parametric || t.method == TessellationMethod::Empty;
  if (!prim.clip.empty() && !prim.isPlanar() && parametric && 4 * t.surface_triangles < std::size_t(target)) {
    PrimitiveTessellation m = tessellateOnce(prim, target, camera, aspect, chordSamples, true);
    if (m.surface_triangles > t.surface_triangles) return m;
  }
  return t;
}

PrimitiveTessellation tessellatePrimitive(const Primitive& prim, const TessellationOptions& options,
                                          const Camera* camera, double aspect) {
  if (options.chord_error <= 0)
    return tessellateCovering(prim, std::max(2, options.triangles), camera, aspect, options.chord_samples);
  int target = 8;
  PrimitiveTessellation t = tessellateCovering(prim, target, camera, aspect, options.chord_samples);
  while (t.max_chord_error > options.chord_error && t.method != TessellationMethod::Planar &&
         t.method != TessellationMethod::Empty && target * 2 <= options.max_triangles) {
    target *= 2;
    t = tessellateCovering(prim, target, camera, aspect, options.chord_samples);
  }
  return t;
}

namespace {

// The triangles of an object's exact surface, at the budget of `pieces` quadric pieces.
ExactSurfaceMesh tessellateExact(const ExactSurface& surface, std::size_t pieces, const TessellationOptions& options) {
  pieces = std::max<std::size_t>(pieces, 1);
  if (options.chord_error <= 0) return surface.tessellate(std::size_t(std::max(2, options.triangles)) * pieces);
  std::size_t budget = 64 * pieces;
  ExactSurfaceMesh m = surface.tessellate(budget);
  while (m.max_error > options.chord_error && 4 * budget <= std::size_t(options.max_triangles) * pieces) {
    budget *= 4;
    ExactSurfaceMesh finer = surface.tessellate(budget);
    const bool same = finer.grid == m.grid;  // the finest grid is reached
    m = std::move(finer);
    if (same) break;
  }
  return m;
}

}  // namespace

TriangleMesh3 tessellateScene(const Scene& scene, const TessellationOptions& options, TessellationReport* report) {
  TriangleMesh3 all;
  TessellationReport rep;
  const double aspect = double(scene.width) / double(scene.height);
  double meanSum = 0;
  std::size_t measured = 0;
  std::vector<bool> exactDone(scene.exact_surfaces.size(), false);
  for (std::size_t i = 0; i < scene.primitives.size(); ++i) {
    const Primitive& p = scene.primitives[i];
    const SceneObject* object =
        p.object >= 0 && std::size_t(p.object) < scene.objects.size() ? &scene.objects[std::size_t(p.object)] : nullptr;
    const int e = object ? object->exact_surface : -1;
    if (e >= 0 && std::size_t(e) < scene.exact_surfaces.size()) {
      // The object's true surface replaces its pieces, drawn once at its first piece.
      if (exactDone[std::size_t(e)]) continue;
      exactDone[std::size_t(e)] = true;
      ExactSurfaceMesh em = tessellateExact(*scene.exact_surfaces[std::size_t(e)], object->count, options);
      TriangleMesh3 t;
      t.positions = std::move(em.positions);
      t.normals = std::move(em.normals);
      t.triangles = std::move(em.triangles);
      const std::size_t n = t.size();
      t.object.assign(n, p.object);
      t.material.assign(n, p.material);
      t.primitive.assign(n, int(i));
      all.append(t);
      ++rep.exact_surfaces;
      rep.exact_triangles += n;
      rep.triangles += n;
      rep.exact_grid = std::max(rep.exact_grid, em.grid);
      rep.max_chord_error = std::max(rep.max_chord_error, em.max_error);
      meanSum += em.mean_error;
      ++measured;
      continue;
    }
    PrimitiveTessellation t = tessellatePrimitive(p, options, &scene.camera, aspect);
    const std::size_t n = t.mesh.size();
    t.mesh.object.assign(n, p.object);
    t.mesh.material.assign(n, p.material);
    t.mesh.primitive.assign(n, int(i));
    all.append(t.mesh);
    ++rep.primitives;
    rep.triangles += n;
    rep.cap_triangles += t.cap_triangles;
    switch (t.method) {
      case TessellationMethod::Parametric: ++rep.parametric; break;
      case TessellationMethod::Planar: ++rep.planar; break;
      case TessellationMethod::MarchingTetrahedra: ++rep.marching; break;
      case TessellationMethod::Empty: ++rep.empty; break;
    }
    rep.max_chord_error = std::max(rep.max_chord_error, t.max_chord_error);
    meanSum += t.mean_chord_error;
    ++measured;
  }
  rep.mean_chord_error = measured ? meanSum / double(measured) : 0.0;
  if (report) *report = rep;
  return all;
}

ChordError measureChordError(const TriangleMesh3& mesh, const Quadric& quadric, std::size_t first, std::size_t count,
                             int subdivisions) {
  ChordError e;
  const std::size_t last = std::min(mesh.triangles.size(), count == std::size_t(-1) ? mesh.triangles.size() : first + count);
  const int m = std::max(1, subdivisions);  // barycentric grid: vertices, edge points, interior points
  double sum = 0;
  std::size_t samples = 0;
  for (std::size_t t = first; t < last; ++t) {
    const Vector3d& a = mesh.positions[std::size_t(mesh.triangles[t][0])];
    const Vector3d& b = mesh.positions[std::size_t(mesh.triangles[t][1])];
    const Vector3d& c = mesh.positions[std::size_t(mesh.triangles[t][2])];
    for (int i = 0; i <= m; ++i)
      for (int j = 0; i + j <= m; ++j) {
        const Vector3d p = (double(i) * a + double(j) * b + double(m - i - j) * c) / double(m);
        const double d = distanceToQuadric(quadric, p);
        e.max = std::max(e.max, d);
        sum += d;
        ++samples;
      }
  }
  e.mean = samples ? sum / double(samples) : 0.0;
  return e;
}

bool isWatertight(const TriangleMesh3& mesh) {
  std::map<Vector3d, int, PointKey> ids;
  auto id = [&](const Vector3d& p) {
    auto it = ids.find(p);
    if (it != ids.end()) return it->second;
    const int n = int(ids.size());
    ids.emplace(p, n);
    return n;
  };
  std::map<std::pair<int, int>, int> edges;
  for (const auto& t : mesh.triangles) {
    int v[3];
    for (int k = 0; k < 3; ++k) v[k] = id(mesh.positions[std::size_t(t[k])]);
    if (v[0] == v[1] || v[1] == v[2] || v[0] == v[2]) return false;
    for (int k = 0; k < 3; ++k) {
      const int a = v[k], b = v[(k + 1) % 3];
      edges[{std::min(a, b), std::max(a, b)}]++;
    }
  }
  if (edges.empty()) return false;
  for (const auto& e : edges)
    if (e.second != 2) return false;
  return true;
}

}  // namespace qacc
