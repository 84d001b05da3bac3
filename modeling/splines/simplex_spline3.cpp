#include "modeling/splines/simplex_spline3.h"

#include <algorithm>
#include <atomic>
#include <cmath>
#include <cstdint>
#include <limits>
#include <stdexcept>

#include "modeling/modelers/bb_quadric.h"
#include "modeling/geometry/convex_polyhedron.h"
#include "modeling/support/parallel_errors.h"

namespace qacc {
namespace {

using Vec = Eigen::Vector3d;

Eigen::Vector4d unitPlane(const Eigen::Vector4d& p) { return p / p.head<3>().norm(); }

// The unit plane up to orientation: its largest normal component (the first of near-ties)
// made positive.
Eigen::Vector4d orientationFree(Eigen::Vector4d u) {
  int m = 0;
  for (int a = 1; a < 3; ++a)
    if (std::fabs(u[a]) > std::fabs(u[m]) + 1e-9) m = a;
  return u[m] < 0 ? Eigen::Vector4d(-u) : u;
}

// 1 or -1 when all values have that strict sign, else 0; values within 1e-12 of the largest
// count as zero (a rounded zero must not decide).
int strictSign(const double* v, int n) {
  double big = 0;
  for (int i = 0; i < n; ++i) big = std::max(big, std::fabs(v[i]));
  bool pos = true, neg = true;
  for (int i = 0; i < n; ++i) {
    pos = pos && v[i] > 1e-12 * big;
    neg = neg && v[i] < -1e-12 * big;
  }
  return pos ? 1 : neg ? -1 : 0;
}

// Sign of f's 10 BB coefficients on t (bb_quadric.h), as strictSign.
int strictSign(const Quadric& f, const Tetrahedron& t) {
  const Eigen::Matrix4d C = BBQuadric::fromQuadric(f, t).C;
  double v[10];
  int k = 0;
  for (int a = 0; a < 4; ++a)
    for (int b = a; b < 4; ++b) v[k++] = C(a, b);
  return strictSign(v, 10);
}

// Bounds of f over the convex hull of `points`, about their centroid m: the affine part is
// exact at the points; of (x - m)ᵀ A (x - m), the part on A's positive eigenvectors is
// convex (>= 0, largest at a point), the rest concave (<= 0, smallest at a point). With
// rough = true the quadratic part is bounded by ±|A|_F ρ² instead (ρ: largest |x - m|).
void bounds(const Quadric& f, const std::vector<ConvexPolyhedron::Vertex>& points, double& lo, double& hi,
            bool rough = false) {
  Vec m = Vec::Zero();
  for (const auto& v : points) m += v.x;
  m /= double(points.size());
  const double fm = f.eval(m);
  const Vec grad = f.gradient(m);
  double rho2 = 0;
  lo = hi = fm;
  for (const auto& v : points) {
    const double l = fm + grad.dot(v.x - m);
    lo = std::min(lo, l);
    hi = std::max(hi, l);
    rho2 = std::max(rho2, (v.x - m).squaredNorm());
  }
  const Eigen::Matrix3d A = f.Q.topLeftCorner<3, 3>();
  const double norm = A.norm();
  if (rough) {
    lo -= norm * rho2;
    hi += norm * rho2;
    return;
  }
  Eigen::SelfAdjointEigenSolver<Eigen::Matrix3d> es;
  es.computeDirect(A);
  double qpos = 0, qneg = 0;
  for (const auto& v : points) {
    const Vec d = es.eigenvectors().transpose() * (v.x - m);
    double p = 0, n = 0;
    for (int i = 0; i < 3; ++i) (es.eigenvalues()[i] > 0 ? p : n) += es.eigenvalues()[i] * d[i] * d[i];
    qpos = std::max(qpos, p);
    qneg = std::min(qneg, n);
  }
  const double slack = 1e-12 * norm * rho2;  // eigen-decomposition error
  lo += qneg - slack;
  hi += qpos + slack;
}

// w Π f_i for n <= 2 affine forms f_i(x) = a_i·x + b_i, as a quadric.
template <class Affine>
Quadric productOf(const Affine* f, int n, double w) {
  const Eigen::Vector4d one(0, 0, 0, 1);
  const Eigen::Vector4d u = n > 0 ? Eigen::Vector4d(f[0].a.x(), f[0].a.y(), f[0].a.z(), f[0].b) : one;
  const Eigen::Vector4d v = n > 1 ? Eigen::Vector4d(f[1].a.x(), f[1].a.y(), f[1].a.z(), f[1].b) : one;
  return Quadric(Eigen::Matrix4d(w * u * v.transpose()));  // symmetrised
}

// Can f vanish in the cell? Not when its values at the corners have one strict sign and its
// BB coefficients have that sign on the parent tetrahedron or on every tetrahedron of a fan
// covering the cell (convex hull property).
bool mayVanish(const Quadric& f, const ConvexPolyhedron& cell, const Tetrahedron& parent,
               const std::vector<Eigen::Vector4d>& unit) {
  std::vector<double> corner;
  for (const auto& v : cell.vertices()) corner.push_back(f.eval(v.x));
  const int sign = strictSign(corner.data(), int(corner.size()));
  if (sign == 0) return true;
  if (strictSign(f, parent) == sign) return false;
  for (const auto& t : cell.fan(unit))
    if (strictSign(f, t) != sign) return true;
  return false;
}

// The planes of a tetrahedron's cells: coefficients as emitted and unit-normal copies for
// distances.
struct PlaneTable {
  std::vector<Eigen::Vector4d> coef, unit;
  int add(const Eigen::Vector4d& p) {
    coef.push_back(p);
    unit.push_back(unitPlane(p));
    return int(coef.size()) - 1;
  }
};

// A cutting plane and the knot triangles on it.
struct PlaneGroup {
  int id = 0;       // in the plane table
  double area = 0;  // of its largest triangle
  std::vector<std::array<Vec, 3>> triangles;
  Eigen::AlignedBox3d box;  // of its triangles
};

// The (canonical) planes of the knot triangles that cross `start`, coinciding planes
// (within 1e-11 relative) merged, largest triangle first.
std::vector<PlaneGroup> cuttingPlanes(const std::vector<std::array<Vec, 3>>& triangles, const ConvexPolyhedron& start,
                                      PlaneTable& planes, double eps) {
  const Eigen::AlignedBox3d startBox = start.box();
  const double scale = startBox.diagonal().norm();
  struct Candidate {
    std::array<Vec, 3> p;
    Eigen::Vector4d plane, key;
    double area;
  };
  std::vector<Candidate> cand;
  for (const auto& p : triangles) {
    Candidate c{p, {}, {}, 0.5 * (p[1] - p[0]).cross(p[2] - p[0]).norm()};
    if (c.area <= eps * scale) continue;  // collinear or coincident knots
    Eigen::AlignedBox3d tb;
    for (const Vec& v : p) tb.extend(v);
    if (!tb.intersects(startBox)) continue;
    c.plane = canonicalPlane(p[0], p[1], p[2]);
    bool neg, pos;
    start.sides(unitPlane(c.plane), eps, neg, pos);
    if (!neg || !pos || !start.crossedBy(p[0], p[1], p[2], planes.unit, eps)) continue;
    c.key = orientationFree(unitPlane(c.plane));
    cand.push_back(std::move(c));
  }
  std::vector<std::size_t> byKey(cand.size());
  for (std::size_t i = 0; i < cand.size(); ++i) byKey[i] = i;
  std::sort(byKey.begin(), byKey.end(), [&](std::size_t a, std::size_t b) {
    return cand[a].key.x() < cand[b].key.x() || (cand[a].key.x() == cand[b].key.x() && a < b);
  });
  const double tol = 1e-11;
  std::vector<bool> taken(cand.size(), false);
  std::vector<PlaneGroup> groups;
  for (std::size_t u = 0; u < byKey.size(); ++u) {
    const std::size_t i = byKey[u];
    if (taken[i]) continue;
    std::vector<std::size_t> members = {i};
    for (std::size_t w = u + 1; w < byKey.size() && cand[byKey[w]].key.x() - cand[i].key.x() <= tol; ++w) {
      const std::size_t j = byKey[w];
      const Eigen::Vector4d d = cand[j].key - cand[i].key;
      if (!taken[j] && d.head<3>().cwiseAbs().maxCoeff() <= tol && std::fabs(d.w()) <= tol * scale) members.push_back(j);
    }
    std::sort(members.begin(), members.end());
    PlaneGroup g;
    g.id = planes.add(cand[members[0]].plane);  // the member first in triangle order
    for (std::size_t j : members) {
      taken[j] = true;
      g.area = std::max(g.area, cand[j].area);
      g.triangles.push_back(cand[j].p);
      for (const Vec& v : cand[j].p) g.box.extend(v);
    }
    groups.push_back(std::move(g));
  }
  std::stable_sort(groups.begin(), groups.end(), [](const PlaneGroup& a, const PlaneGroup& b) { return a.area > b.area; });
  return groups;
}

// F near one tetrahedron, as a sum over the leaves of the compiled basis functions:
// F(u) = Σ_k c_k N_k(u), N_k(u) = Σ_{leaves L of k} 1_L(u) w_L Π λ(u). Leaves of several
// basis functions share knot simplices (about 4 leaves per simplex), so the sum is kept per
// distinct simplex S: F = Σ_S 1_S(u) T_S(u), T_S = Σ_{leaves on S} c w Π λ, a quadric. A
// region of the tetrahedron carries a State: the sum of the T_S of the simplices that
// contain it and the list of those it straddles (the ones it misses are forgotten).
// classify() refines a child's State from its parent's and bounds F on the region:
//   F ∈ range(contained sum) + Σ over straddled S of [min(0, T_S), max(0, T_S)],
// ranges over the region taken from its corners (bounds above), those of T_S also
// intersected with T_S's range on S (its extreme BB coefficients there).
class LocalField {
 public:
  struct Straddled {
    std::uint32_t simplex;
    std::uint8_t faces;  // bit j: the region has corners on both sides of face j
  };
  struct State {
    Quadric all;                     // Σ T_S over the contained S
    std::vector<Straddled> partial;  // straddled simplices
  };

  LocalField(const SimplexSpline3& s, const std::vector<std::size_t>& near) {
    const auto& B = s.basisFunctions();
    const int n = s.degree();
    struct Item {
      std::array<int, 4> key;
      std::size_t basis, leaf;
    };
    std::vector<Item> items;
    for (std::size_t i : near) {
      if (s.coefficientOf(B[i]) == 0.0) continue;
      for (std::size_t l = 0; l < B[i].leaves.size(); ++l) {
        Item it{B[i].leaves[l].knots, i, l};
        std::sort(it.key.begin(), it.key.end());
        items.push_back(it);
      }
    }
    std::stable_sort(items.begin(), items.end(), [](const Item& a, const Item& b) { return a.key < b.key; });
    for (std::size_t i = 0; i < items.size(); ++i) {
      const auto& L = B[items[i].basis].leaves[items[i].leaf];
      if (i == 0 || items[i].key != items[i - 1].key) {
        Simplex S;
        S.leaf = &L;
        S.knots = items[i].key;
        for (int j = 0; j < 4; ++j) {
          const auto& f = L.bary[std::size_t(j)];
          S.bary[std::size_t(j)] = Eigen::Vector4d(f.a.x(), f.a.y(), f.a.z(), f.b);
        }
        for (int id : S.knots) S.box.extend(s.knotById(id));
        simplices_.push_back(S);
      }
      const double c = s.coefficientOf(B[items[i].basis]);
      simplices_.back().term.Q += productOf(&B[items[i].basis].factors[items[i].leaf * std::size_t(n)], n, c * L.weight).Q;
    }
    // T_S over S lies between its extreme BB coefficients there (convex hull property).
    for (Simplex& S : simplices_) {
      Tetrahedron t;
      for (int a = 0; a < 4; ++a) t[std::size_t(a)] = s.knotById(S.knots[std::size_t(a)]);
      const Eigen::Matrix4d C = BBQuadric::fromQuadric(S.term, t).C;
      S.lo = S.hi = C(0, 0);
      for (int a = 0; a < 4; ++a)
        for (int b = a; b < 4; ++b) {
          S.lo = std::min(S.lo, C(a, b));
          S.hi = std::max(S.hi, C(a, b));
        }
    }
  }

  const std::array<int, 4>& knots(std::uint32_t simplex) const { return simplices_[simplex].knots; }

  State root() const {
    State st;
    for (std::uint32_t l = 0; l < simplices_.size(); ++l) st.partial.push_back(Straddled{l, 0xF});
    return st;
  }

  // Refines st against `region`; lo, hi bound F on it.
  void classify(const ConvexPolyhedron& region, State& st, double& lo, double& hi) const {
    const auto& V = region.vertices();
    const std::size_t nv = V.size();
    const Eigen::AlignedBox3d box = region.box();
    const double tau = 1e-11;  // on barycentric coordinates
    double slo = 0, shi = 0;
    std::size_t keep = 0;
    for (std::size_t q = 0; q < st.partial.size(); ++q) {
      Straddled& p = st.partial[q];
      const Simplex& S = simplices_[p.simplex];
      if (!S.box.intersects(box)) continue;
      // Out: all corners beyond one face; in: all corners inside every face. A face the
      // parent region lay inside of is not looked at again.
      bool out = false;
      for (int j = 0; j < 4 && !out; ++j) {
        if (!(p.faces & (1u << j))) continue;
        const Eigen::Vector4d& f = S.bary[std::size_t(j)];
        bool pos = false, neg = false;
        for (std::size_t v = 0; v < nv && !(pos && neg); ++v) {
          const double x = f.head<3>().dot(V[v].x) + f.w();
          pos = pos || x > tau;
          neg = neg || x < -tau;
        }
        out = !pos;
        if (!neg) p.faces = std::uint8_t(p.faces & ~(1u << j));
      }
      if (out) continue;
      if (p.faces == 0) {
        st.all.Q += S.term.Q;
        continue;
      }
      double tl, th;  // T_S on region ∩ S
      bounds(S.term, V, tl, th, true);
      slo += std::min(0.0, std::max(tl, S.lo));
      shi += std::max(0.0, std::min(th, S.hi));
      st.partial[keep++] = p;
    }
    st.partial.resize(keep);
    bounds(st.all, V, lo, hi);
    lo += slo;
    hi += shi;
  }

  // F on a cell: simplices still straddled (only within the tolerances) decide at its centroid.
  Quadric polynomial(const State& st, const Vec& centre) const {
    Quadric f = st.all;
    for (const Straddled& p : st.partial)
      if (SimplexSpline3::inside(*simplices_[p.simplex].leaf, centre)) f.Q += simplices_[p.simplex].term.Q;
    return f;
  }

 private:
  struct Simplex {
    const SimplexSpline3::Leaf* leaf;     // one leaf on it (its barycentric forms)
    std::array<Eigen::Vector4d, 4> bary;  // the same, packed
    std::array<int, 4> knots;             // sorted
    Eigen::AlignedBox3d box;
    Quadric term;           // T_S
    double lo = 0, hi = 0;  // bounds of T_S on S
  };
  std::vector<Simplex> simplices_;
};

// The tetrahedron as a region (its faces first in the plane table: a face shared with a
// neighbour gets the opposite half-space there), clipped to the domain box when there is one.
ConvexPolyhedron tetRegion(const Tetrahedron& tet, const Eigen::AlignedBox3d& domain, PlaneTable& planes, double eps) {
  std::array<int, 4> faceId;
  for (int a = 0; a < 4; ++a)
    faceId[std::size_t(a)] = planes.add(facePlane(tet[std::size_t((a + 1) % 4)], tet[std::size_t((a + 2) % 4)],
                                                  tet[std::size_t((a + 3) % 4)], tet[std::size_t(a)]).p);
  ConvexPolyhedron start = ConvexPolyhedron::tetrahedron(tet, faceId, {false, false, false, false});
  if (!domain.isEmpty())
    for (int axis = 0; axis < 3 && !start.empty(); ++axis) {
      Eigen::Vector4d lo = Eigen::Vector4d::Zero(), hi = Eigen::Vector4d::Zero();
      lo[axis] = -1;
      lo[3] = domain.min()[axis];
      hi[axis] = 1;
      hi[3] = -domain.max()[axis];
      start = start.clipped(planes.add(lo), false, planes.unit, eps);
      if (!start.empty()) start = start.clipped(planes.add(hi), false, planes.unit, eps);
    }
  return start;
}

// The faces (knot triples) of the straddled simplices, each once, sorted: F is one
// polynomial between them, so they are the cuts.
std::vector<std::array<int, 3>> straddledFaces(const LocalField& field, const LocalField::State& st) {
  std::vector<std::array<int, 3>> triples;
  for (const auto& p : st.partial) {
    const auto& k = field.knots(p.simplex);  // sorted
    triples.push_back({k[1], k[2], k[3]});
    triples.push_back({k[0], k[2], k[3]});
    triples.push_back({k[0], k[1], k[3]});
    triples.push_back({k[0], k[1], k[2]});
  }
  std::sort(triples.begin(), triples.end());
  triples.erase(std::unique(triples.begin(), triples.end()), triples.end());
  return triples;
}

// Does a triangle of the group (whose plane is known to cut the region) cross its interior?
bool trianglesCross(const PlaneGroup& g, const ConvexPolyhedron& poly, const Eigen::AlignedBox3d& box,
                    const PlaneTable& planes, double eps) {
  for (const auto& tr : g.triangles) {
    Eigen::AlignedBox3d tb;
    for (const Vec& v : tr) tb.extend(v);
    if (tb.intersects(box) && poly.crossedBy(tr[0], tr[1], tr[2], planes.unit, eps)) return true;
  }
  return false;
}

// A region of the recursive cutting of a tetrahedron.
struct CutRegion {
  ConvexPolyhedron poly;
  std::vector<std::uint32_t> planes;  // groups that may still cross it, in order
  LocalField::State state;
  bool classified;
};

// The plane that cuts r: among the first 16 of its list (largest triangle first) that cut
// it, the one that leaves the most of it on its thinner side and one of whose triangles
// crosses it; planes found not to cut r, or whose triangles miss it, are dropped from
// r.planes. Returns the index in r.planes, r.planes.size() when none cuts.
std::size_t pickCut(CutRegion& r, const std::vector<PlaneGroup>& groups, const PlaneTable& planes, double eps) {
  const Eigen::AlignedBox3d box = r.poly.box();
  std::size_t best = r.planes.size();
  for (bool more = true; more && best == r.planes.size();) {
    std::vector<std::pair<double, std::size_t>> cutting;  // (depth, index in r.planes)
    std::vector<char> drop(r.planes.size(), 0);
    for (std::size_t k = 0; k < r.planes.size() && cutting.size() < 16; ++k) {
      const PlaneGroup& g = groups[r.planes[k]];
      double mn = 0, mx = 0;
      if (g.box.intersects(box))
        for (const auto& v : r.poly.vertices()) {
          const double x = planes.unit[std::size_t(g.id)].head<3>().dot(v.x) + planes.unit[std::size_t(g.id)].w();
          mn = std::min(mn, x);
          mx = std::max(mx, x);
        }
      if (mn < -eps && mx > eps)
        cutting.emplace_back(std::min(-mn, mx), k);
      else
        drop[k] = 1;
    }
    more = cutting.size() == 16;  // when all 16 fail, look further down the list
    std::stable_sort(cutting.begin(), cutting.end(), [](const auto& x, const auto& y) { return x.first > y.first; });
    for (const auto& [depth, k] : cutting) {
      if (trianglesCross(groups[r.planes[k]], r.poly, box, planes, eps)) {
        best = k;
        break;
      }
      drop[k] = 1;
    }
    std::vector<std::uint32_t> kept;
    std::size_t keptBest = 0;
    for (std::size_t k = 0; k < r.planes.size(); ++k) {
      if (k == best) keptBest = kept.size();
      if (!drop[k]) kept.push_back(r.planes[k]);
    }
    r.planes.swap(kept);
    if (best < kept.size()) best = keptBest;
    else best = r.planes.size();
  }
  return best;
}

}  // namespace

SimplexSpline3::CellStats& SimplexSpline3::CellStats::operator+=(const CellStats& o) {
  tets += o.tets;
  tets_culled += o.tets_culled;
  regions_culled += o.regions_culled;
  cells += o.cells;
  crossed += o.crossed;
  planes += o.planes;
  view_culled += o.view_culled;
  regions += o.regions;
  return *this;
}

SimplexSpline3::RegionLimitExceeded::RegionLimitExceeded(std::size_t regions_, std::size_t sampled_, std::size_t tets_)
    : std::runtime_error("the cell decomposition needs " + std::string(sampled_ ? "about " : "more than ") +
                         std::to_string(sampled_ ? regions_ : regions_ - 1) + " regions"),
      regions(regions_),
      sampled(sampled_),
      tets(tets_) {}

// The regions made so far by all threads, against the limit.
struct SimplexSpline3::RegionCount {
  std::atomic<std::size_t> made{0};
  std::size_t limit = SIZE_MAX;
  std::size_t tets = 0;
  void add(std::size_t k, CellStats& stats) {
    stats.regions += k;
    if (made.fetch_add(k, std::memory_order_relaxed) + k > limit) throw RegionLimitExceeded(limit + 1, 0, tets);
  }
};

namespace {

// False only when the region lies outside the view volume (true without a view).
bool mayBeSeen(const ConvexPolyhedron& region, const ViewVolume* view) {
  if (!view) return true;
  std::vector<Eigen::Vector3d> corners;
  for (const auto& v : region.vertices()) corners.push_back(v.x);
  return view->mayContain(corners);
}

}  // namespace

std::vector<SimplexSpline3::Cell> SimplexSpline3::decomposeTet(std::size_t t, bool cull, double eps,
                                                               CellStats& stats, const ViewVolume* view,
                                                               RegionCount& regions) const {
  std::vector<Cell> out;
  const auto& T = simplices_[t];
  Tetrahedron tet;
  for (int a = 0; a < 4; ++a) tet[std::size_t(a)] = verts_[std::size_t(T[std::size_t(a)])];
  PlaneTable planes;
  const ConvexPolyhedron start = tetRegion(tet, domain_, planes, eps);
  if (start.empty()) return out;
  ++stats.tets;
  regions.add(1, stats);
  if (!mayBeSeen(start, view)) {
    ++stats.view_culled;
    return out;
  }

  // Basis functions whose support box overlaps the region with volume (all those not zero
  // in its interior): when none changes sign, F does not either.
  const Eigen::AlignedBox3d startBox = start.box();
  std::vector<std::size_t> near;
  for (std::size_t i : basisNear(startBox)) {
    const Eigen::AlignedBox3d overlap = basisFunctions()[i].support.intersection(startBox);
    if ((overlap.sizes().array() > eps).all()) near.push_back(i);
  }
  if (cull) {
    bool pos = !near.empty(), neg = !near.empty();
    for (std::size_t i : near) {
      pos = pos && coefficientOf(basisFunctions()[i]) > 0;
      neg = neg && coefficientOf(basisFunctions()[i]) < 0;
    }
    if (pos || neg) {
      ++stats.tets_culled;
      ++stats.regions_culled;
      return out;
    }
  }
  const LocalField field(*this, near);
  LocalField::State rootState = field.root();
  double rlo, rhi;
  field.classify(start, rootState, rlo, rhi);

  // Cuts: the faces of the straddled simplices.
  const std::vector<std::array<int, 3>> triples = straddledFaces(field, rootState);
  std::vector<std::array<Vec, 3>> triangles;
  for (const auto& tr : triples) triangles.push_back({knotById(tr[0]), knotById(tr[1]), knotById(tr[2])});
  const std::vector<PlaneGroup> groups = cuttingPlanes(triangles, start, planes, eps);
  stats.planes += groups.size();

  // Recursive cutting, depth first (negative side first): deterministic. A region is cut by
  // the plane, among the first 16 of its list (largest triangle first) that cut it, that
  // leaves the most of it on its thinner side and one of whose triangles crosses it
  // (balanced cuts shrink regions fastest, and their bounds with them). Planes found not to
  // cut the region, or whose triangles miss it, are dropped for the whole subtree.
  std::vector<CutRegion> stack;
  {
    CutRegion root{start, {}, std::move(rootState), true};
    for (std::uint32_t g = 0; g < groups.size(); ++g) root.planes.push_back(g);
    stack.push_back(std::move(root));
  }
  while (!stack.empty()) {
    CutRegion r = std::move(stack.back());
    stack.pop_back();
    if (!mayBeSeen(r.poly, view)) {
      ++stats.view_culled;
      continue;
    }
    double lo = rlo, hi = rhi;
    if (!r.classified) field.classify(r.poly, r.state, lo, hi);
    if (r.state.partial.empty()) r.planes.clear();  // one polynomial: no simplex face crosses it
    if (cull && !r.state.partial.empty()) {
      const double margin = 1e-12 * (std::fabs(lo) + std::fabs(hi));
      if (lo > margin || hi < -margin) {
        ++stats.regions_culled;
        continue;
      }
    }
    const std::size_t best = pickCut(r, groups, planes, eps);
    if (best < r.planes.size()) {
      CutRegion a{{}, {}, {}, false}, b{{}, {}, {}, false};
      if (!r.poly.split(groups[r.planes[best]].id, planes.unit, eps, a.poly, b.poly))
        throw std::logic_error("SimplexSpline3: a crossing plane did not cut");
      regions.add(2, stats);
      a.planes = r.planes;
      a.planes.erase(a.planes.begin() + std::ptrdiff_t(best));
      b.planes = a.planes;
      b.state = r.state;
      a.state = std::move(r.state);
      stack.push_back(std::move(b));
      stack.push_back(std::move(a));
      continue;
    }

    Cell cell;
    cell.parent = t;
    cell.quadric = field.polynomial(r.state, r.poly.centroid());
    for (const auto& v : r.poly.vertices()) cell.corners.push_back(v.x);
    for (const auto& face : r.poly.faces()) {
      const HalfSpace h(planes.coef[std::size_t(face.plane)]);
      cell.faces.push_back(face.flip ? h.opposite() : h);
    }
    cell.crossed = mayVanish(cell.quadric, r.poly, tet, planes.unit);
    ++stats.cells;
    stats.crossed += cell.crossed;
    if (cell.crossed || !cull) out.push_back(std::move(cell));
  }
  return out;
}

std::vector<SimplexSpline3::Cell> SimplexSpline3::decompose(bool cull, CellStats* stats, const ViewVolume* view,
                                                            std::size_t maxRegions) const {
  if (n_ > 2) throw std::invalid_argument("SimplexSpline3: cells are made for degree <= 2");
  Eigen::AlignedBox3d all;
  for (const Vec& v : verts_) all.extend(v);
  const double eps = 1e-10 * all.diagonal().norm();
  const std::size_t n = simplices_.size();
  std::vector<std::vector<Cell>> per(n);
  std::vector<CellStats> st(n);
  RegionCount regions;
  regions.limit = maxRegions;
  regions.tets = n;
  // The sample first (every tetrahedron when there are few), then the others.
  const std::size_t sampled = std::min(n, kRegionSample);
  std::vector<std::size_t> order;
  std::vector<char> inSample(n, 0);
  for (std::size_t k = 0; k < sampled; ++k) {
    const std::size_t t = (2 * k + 1) * n / (2 * sampled);
    inSample[t] = 1;
    order.push_back(t);
  }
  const std::size_t sampleEnd = order.size();
  for (std::size_t t = 0; t < n; ++t)
    if (!inSample[t]) order.push_back(t);
  auto run = [&](std::size_t begin, std::size_t end) {
    ParallelErrors errors;
#pragma omp parallel for schedule(dynamic, 1)
    for (long long i = (long long)begin; i < (long long)end; ++i)
      errors.run([&] {
        const std::size_t t = order[std::size_t(i)];
        per[t] = decomposeTet(t, cull, eps, st[t], view, regions);
      });
    errors.rethrow();
  };
  run(0, sampleEnd);
  if (sampleEnd < n) {
    const double perTet = double(regions.made.load()) / double(sampleEnd);
    const double estimate = perTet * double(n);
    if (estimate > 2.0 * double(maxRegions))
      throw RegionLimitExceeded(estimate >= double(SIZE_MAX) ? SIZE_MAX : std::size_t(std::ceil(estimate)), sampleEnd, n);
  }
  run(sampleEnd, n);
  std::vector<Cell> out;
  CellStats total;
  for (std::size_t t = 0; t < n; ++t) {
    total += st[t];
    for (Cell& c : per[t]) out.push_back(std::move(c));
  }
  if (stats) *stats = total;
  return out;
}

std::vector<SimplexSpline3::Cell> SimplexSpline3::cells(CellStats* stats) const { return decompose(false, stats); }

std::vector<SimplexSpline3::Cell> SimplexSpline3::crossedCells(CellStats* stats) const {
  return decompose(true, stats);
}

std::vector<Primitive> SimplexSpline3::toPrimitives(int material, int object, CellStats* stats, bool cull,
                                                    const ViewVolume* view, std::size_t maxRegions) const {
  std::vector<Primitive> out;
  for (Cell& c : decompose(cull, stats, view, maxRegions)) {
    Primitive prim;
    prim.quadric = c.quadric;
    prim.clip = std::move(c.faces);
    prim.material = material;
    prim.object = object;
    out.push_back(std::move(prim));
  }
  return out;
}

}  // namespace qacc
