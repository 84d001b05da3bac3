#include "modeling/modelers/macropatch.h"

#include <algorithm>
#include <cmath>
#include <map>
#include <stdexcept>

#include "modeling/geometry/natural_quadrics.h"

namespace qacc {

namespace {

using Eigen::MatrixXd;
using Eigen::Vector3d;
using Eigen::Vector4d;
using Eigen::VectorXd;

using Key = std::array<double, 3>;
Key keyOf(const Vector3d& p) { return {p.x(), p.y(), p.z()}; }

// Index of the upper-triangle entry (a <= b) among a cell's 10 unknowns.
int entryIndex(int a, int b) {
  if (a > b) std::swap(a, b);
  static const int table[4][4] = {{0, 4, 5, 6}, {4, 1, 7, 8}, {5, 7, 2, 9}, {6, 8, 9, 3}};
  return table[a][b];
}

struct Row {
  std::vector<std::pair<int, double>> terms;
  double rhs = 0;
};

// Vertex of a cell at a given position, or -1.
int vertexAt(const Tetrahedron& t, const Vector3d& p) {
  for (int a = 0; a < 4; ++a)
    if (t[a] == p) return a;
  return -1;
}

bool sharesFace(const Tetrahedron& s, const Tetrahedron& t) {
  int n = 0;
  for (int a = 0; a < 4; ++a)
    if (vertexAt(t, s[a]) >= 0) ++n;
  return n == 3;
}

// Corner data shared by every net touching a corner (exact position match).
struct CornerData {
  Vector3d normal_sum = Vector3d::Zero();
  double length_sum = 0;
  int length_count = 0;
  Vector3d gradient = Vector3d::Zero();
};

const int kCorner[3] = {0, 2, 4};
// Controls adjacent to corner index 0, 2, 4: (previous, next) around the net.
int controlBefore(int corner) { return (corner + 5) % 6; }
int controlAfter(int corner) { return corner + 1; }

std::map<Key, CornerData> cornerData(const std::vector<ControlNet>& nets) {
  std::map<Key, CornerData> corners;
  for (const auto& net : nets) {
    for (int ci : kCorner) {
      const Vector3d& v = net[std::size_t(ci)];
      const Vector3d& c1 = net[std::size_t(controlAfter(ci))];
      const Vector3d& c2 = net[std::size_t(controlBefore(ci))];
      Vector3d n = (c1 - v).cross(c2 - v);
      if (!(n.norm() > 0)) throw std::invalid_argument("macropatch: a corner and its two tangent controls are collinear");
      n.normalize();
      // Outward: away from the other two corners (the inside of the corner triangle).
      const Vector3d inward = 0.5 * (net[std::size_t((ci + 2) % 6)] + net[std::size_t((ci + 4) % 6)]) - v;
      if (n.dot(inward) > 0) n = -n;
      CornerData& d = corners[keyOf(v)];
      d.normal_sum += n;
      d.length_sum += (c1 - v).norm() + (c2 - v).norm();
      d.length_count += 2;
    }
  }
  for (auto& kv : corners) {
    CornerData& d = kv.second;
    if (!(d.normal_sum.norm() > 1e-12)) throw std::invalid_argument("macropatch: opposite corner normals cancel");
    const double s = d.length_count / d.length_sum;
    d.gradient = s * d.normal_sum.normalized();
  }
  return corners;
}

void checkNet(const ControlNet& net) {
  for (int i = 0; i < 6; ++i)
    for (int j = i + 1; j < 6; ++j)
      if (net[std::size_t(i)] == net[std::size_t(j)]) throw std::invalid_argument("macropatch: control net has coincident points");
  const Vector3d n = (net[2] - net[0]).cross(net[4] - net[0]);
  if (!(n.norm() > 0)) throw std::invalid_argument("macropatch: the three corners are collinear");
}

void checkCell(const Tetrahedron& t) {
  const double scale = std::max({(t[1] - t[0]).norm(), (t[2] - t[0]).norm(), (t[3] - t[0]).norm()});
  if (!(std::abs(BBQuadric::signedVolume(t)) > 1e-12 * scale * scale * scale))
    throw std::invalid_argument("macropatch: flat tetrahedron (the apex lies in a face plane of the control net)");
}

// The Bézier triangle's tangents ∂B/∂u − ∂B/∂w and ∂B/∂v − ∂B/∂w at (u, v, w).
std::array<Vector3d, 2> bezierTriangleTangents(const ControlNet& P, double u, double v, double w) {
  const Vector3d Bu = 2 * (u * P[0] + v * P[1] + w * P[5]), Bv = 2 * (v * P[2] + u * P[1] + w * P[3]),
                 Bw = 2 * (w * P[4] + v * P[3] + u * P[5]);
  return {Bu - Bw, Bv - Bw};
}

// A sample of the net's Bézier triangle for the least-squares fits: the point X, its two
// tangents, the cell whose tetrahedron holds it (the largest smallest barycentric
// coordinate λ = W X, above −1e-9) and λ there.
struct TriangleSample {
  Vector3d X;
  std::array<Vector3d, 2> tangents;
  std::size_t cell = 0;
  Vector4d lambda;
};

// Samples on the (u, v, w) grid of step 1/k (k = max(2, fitSamples)); samples outside
// every cell are left out. W[t] maps a point to the barycentric coordinates of cell t.
std::vector<TriangleSample> triangleSamples(const ControlNet& P, const std::vector<Eigen::Matrix4d>& W,
                                            int fitSamples) {
  std::vector<TriangleSample> out;
  const int k = std::max(2, fitSamples);
  for (int i = 0; i <= k; ++i)
    for (int j = 0; i + j <= k; ++j) {
      const double u = double(i) / k, v = double(j) / k, w = 1.0 - u - v;
      TriangleSample s;
      s.X = bezierTrianglePoint(P, u, v, w);
      int best = -1;
      double bestMin = -1e-9;
      for (std::size_t t = 0; t < W.size(); ++t) {
        const Vector4d lam = W[t] * s.X.homogeneous();
        if (lam.minCoeff() > bestMin) {
          bestMin = lam.minCoeff();
          best = int(t);
          s.lambda = lam;
        }
      }
      if (best < 0) continue;
      s.cell = std::size_t(best);
      s.tangents = bezierTriangleTangents(P, u, v, w);
      out.push_back(s);
    }
  return out;
}

// ---- G0: 4 cells with constant coefficients ---------------------------------------------

void buildG0(const ControlNet& P, int patch, const MacropatchOptions& o, std::vector<MacropatchCell>& out) {
  const Vector3d A = (P[1] + P[3] + P[5]) / 3.0;
  {
    MacropatchCell c;
    c.patch = patch;
    c.bb.V = {P[0], P[2], P[4], A};
    for (int a = 0; a < 3; ++a) {
      c.bb.C(a, a) = 0;
      c.bb.C(a, 3) = c.bb.C(3, a) = o.corner_apex;
      for (int b = a + 1; b < 3; ++b) c.bb.C(a, b) = c.bb.C(b, a) = -2.0;
    }
    c.bb.C(3, 3) = o.apex;
    checkCell(c.bb.V);
    out.push_back(c);
  }
  for (int e = 0; e < 3; ++e) {
    const int ia = kCorner[e], ib = kCorner[(e + 1) % 3], ic = ia + 1;
    MacropatchCell c;
    c.patch = patch;
    c.bb.V = {P[std::size_t(ia)], P[std::size_t(ic)], P[std::size_t(ib)], A};  // (Pa, Pc, Pb, A)
    Eigen::Matrix4d C = Eigen::Matrix4d::Zero();
    C(1, 1) = 1.0;                              // control
    C(0, 2) = C(2, 0) = -2.0;                   // chord
    C(0, 3) = C(3, 0) = C(2, 3) = C(3, 2) = o.corner_apex;
    C(1, 3) = C(3, 1) = o.control_apex;
    C(3, 3) = o.apex;
    c.bb.C = C;
    checkCell(c.bb.V);
    out.push_back(c);
  }
}

// G0 constants fitted to the net's Bézier triangle: f is affine in (apex, corner_apex,
// control_apex), so f = 0 and ∇f ⟂ Bézier tangents at sample points is a 3-unknown linear
// least-squares problem; constants that come out negative are fixed at 0 and the rest
// refitted (>= 0 keeps the surface off the outer faces).
MacropatchOptions fitG0Constants(const ControlNet& P, const MacropatchOptions& o) {
  auto cellsWith = [&](double a, double c, double t) {
    MacropatchOptions k = o;
    k.apex = a;
    k.corner_apex = c;
    k.control_apex = t;
    std::vector<MacropatchCell> cells;
    buildG0(P, 0, k, cells);
    return cells;
  };
  const auto base = cellsWith(0, 0, 0);
  const std::array<std::vector<MacropatchCell>, 3> unit = {cellsWith(1, 0, 0), cellsWith(0, 1, 0), cellsWith(0, 0, 1)};
  std::vector<Eigen::Matrix4d> W;
  for (const auto& c : base) W.push_back(BBQuadric::vertexMatrix(c.bb.V).transpose().inverse());
  std::vector<std::array<double, 4>> rows;  // 3 coefficients + constant term
  for (const TriangleSample& s : triangleSamples(P, W, o.fit_samples)) {
    const std::size_t b = s.cell;
    auto value = [&](const BBQuadric& bb) { return bb.toQuadric().eval(s.X); };
    auto slope = [&](const BBQuadric& bb, const Vector3d& tv) { return o.normal_weight * bb.toQuadric().gradient(s.X).dot(tv); };
    const double f0 = value(base[b].bb);
    rows.push_back({value(unit[0][b].bb) - f0, value(unit[1][b].bb) - f0, value(unit[2][b].bb) - f0, f0});
    for (const Vector3d& tv : s.tangents) {
      const double g0 = slope(base[b].bb, tv);
      rows.push_back({slope(unit[0][b].bb, tv) - g0, slope(unit[1][b].bb, tv) - g0, slope(unit[2][b].bb, tv) - g0, g0});
    }
  }
  std::array<bool, 3> active = {true, true, true};
  Eigen::Vector3d x = Eigen::Vector3d::Zero();
  for (int round = 0; round < 3; ++round) {
    Eigen::Matrix3d H = Eigen::Matrix3d::Zero();
    Eigen::Vector3d g = Eigen::Vector3d::Zero();
    for (const auto& r : rows)
      for (int a = 0; a < 3; ++a) {
        if (!active[std::size_t(a)]) continue;
        g[a] -= r[std::size_t(a)] * r[3];
        for (int c = 0; c < 3; ++c)
          if (active[std::size_t(c)]) H(a, c) += r[std::size_t(a)] * r[std::size_t(c)];
      }
    for (int a = 0; a < 3; ++a)
      if (!active[std::size_t(a)]) H(a, a) = 1.0, g[a] = 0.0;
    x = H.ldlt().solve(g);
    bool changed = false;
    for (int a = 0; a < 3; ++a)
      if (active[std::size_t(a)] && !(x[a] >= 0)) active[std::size_t(a)] = false, changed = true;
    if (!changed) break;
  }
  MacropatchOptions fitted = o;
  fitted.apex = std::max(0.0, x[0]);
  fitted.corner_apex = std::max(0.0, x[1]);
  fitted.control_apex = std::max(0.0, x[2]);
  return fitted;
}

// ---- G1: 18 cells, exact constraints + fit -------------------------------------------------

struct BoundaryFace {
  int cell;
  Vector3d pa, m, pb, pc;  // corners, midpoint, control; this cell holds (pa, m, pc)
};
struct G1Cells {
  std::vector<Tetrahedron> cells;     // 18: central, edge and filling cells
  std::vector<BoundaryFace> boundary; // the cells' faces on the macropatch's boundary
};

// The 18 cells of a G1 macropatch around its apex A (centroid of the controls) and the
// centroid O of the corners.
G1Cells g1Cells(const ControlNet& P) {
  const Vector3d A = (P[1] + P[3] + P[5]) / 3.0;
  const Vector3d O = (P[0] + P[2] + P[4]) / 3.0;
  G1Cells g;
  std::vector<Tetrahedron>& cells = g.cells;
  std::vector<BoundaryFace>& boundary = g.boundary;
  for (int e = 0; e < 3; ++e) {
    const int ia = kCorner[e], ib = kCorner[(e + 1) % 3], ic = ia + 1;
    const Vector3d &pa = P[std::size_t(ia)], &pb = P[std::size_t(ib)], &pc = P[std::size_t(ic)];
    const Vector3d M = 0.5 * (pa + pb);
    cells.push_back({pa, M, O, A});  // central
    cells.push_back({M, pb, O, A});
    boundary.push_back({int(cells.size()), pa, M, pb, pc});
    cells.push_back({pa, M, pc, A});  // edge
    boundary.push_back({int(cells.size()), pb, M, pa, pc});
    cells.push_back({M, pb, pc, A});
  }
  for (int ci : kCorner) {
    const Vector3d& v = P[std::size_t(ci)];
    const Vector3d& c1 = P[std::size_t(controlAfter(ci))];
    const Vector3d& c2 = P[std::size_t(controlBefore(ci))];
    const Vector3d m = 0.5 * (c1 + c2);
    cells.push_back({v, c1, m, A});  // filling
    cells.push_back({v, m, c2, A});
  }
  for (const auto& t : cells) checkCell(t);
  return g;
}

// One coefficient of one cell fixed to a value.
void setEntry(std::vector<Row>& rows, int cell, int a, int b, double value) {
  rows.push_back({{{10 * cell + entryIndex(a, b), 1.0}}, value});
}

void cornerRows(const ControlNet& P, const std::vector<Tetrahedron>& cells, const std::map<Key, CornerData>& corners,
                std::vector<Row>& rows) {
  const int n = int(cells.size());
  auto set = [&](int cell, int a, int b, double value) { setEntry(rows, cell, a, b, value); };
  // Corners: value 0 and the shared gradient.
  for (int t = 0; t < n; ++t)
    for (int ci : kCorner) {
      const int a = vertexAt(cells[std::size_t(t)], P[std::size_t(ci)]);
      if (a < 0) continue;
      const Vector3d g = corners.at(keyOf(P[std::size_t(ci)])).gradient;
      set(t, a, a, 0.0);
      for (int b = 0; b < 4; ++b)
        if (b != a) set(t, a, b, 0.5 * g.dot(cells[std::size_t(t)][std::size_t(b)] - P[std::size_t(ci)]));
    }
}

void boundaryRows(const G1Cells& g, const std::map<Key, CornerData>& corners, const MacropatchOptions& o,
                  std::vector<Row>& rows) {
  const std::vector<Tetrahedron>& cells = g.cells;
  const std::vector<BoundaryFace>& boundary = g.boundary;
  auto set = [&](int cell, int a, int b, double value) { setEntry(rows, cell, a, b, value); };
  // Boundary faces: data from (Pa, Pb, Pc, g_a, g_b) only.
  for (const auto& bf : boundary) {
    const Vector3d ga = corners.at(keyOf(bf.pa)).gradient, gb = corners.at(keyOf(bf.pb)).gradient;
    const double a = 0.5 * ga.dot(bf.m - bf.pa), b = 0.5 * gb.dot(bf.m - bf.pb);
    const double ta = 0.5 * ga.dot(bf.pc - bf.pa), tb = 0.5 * gb.dot(bf.pc - bf.pb);
    const Tetrahedron& t = cells[std::size_t(bf.cell)];
    const int ia = vertexAt(t, bf.pa), im = vertexAt(t, bf.m), ic = vertexAt(t, bf.pc);
    set(bf.cell, ia, ia, 0.0);
    set(bf.cell, ia, im, a);
    set(bf.cell, ia, ic, ta);
    set(bf.cell, im, im, 0.5 * (a + b));
    set(bf.cell, im, ic, 0.5 * (ta + tb));
    set(bf.cell, ic, ic, -0.5 * (a + b));
    if (!o.cross_boundary) continue;
    // Cross-boundary derivative ∇f·ν on the face, affine, from shared data only: ν from the
    // boundary triangle's points sorted (same on both sides), g_a·ν and g_b·ν at the corners,
    // their mean at M and at Pc. Equal face values + equal ∇f·ν ⇒ the two macropatches'
    // quadrics differ by μ p² on this face: G1 between macropatches.
    std::array<Vector3d, 3> tri = {bf.pa, bf.pb, bf.pc};
    std::sort(tri.begin(), tri.end(), [](const Vector3d& p, const Vector3d& q) { return keyOf(p) < keyOf(q); });
    const Vector3d nu = (tri[1] - tri[0]).cross(tri[2] - tri[0]).normalized();
    const double lmid = 0.5 * (ga.dot(nu) + gb.dot(nu));
    const Eigen::Matrix4d Wt = BBQuadric::vertexMatrix(t).transpose().inverse();
    for (const int iv : {im, ic}) {
      Row r;
      for (int bq = 0; bq < 4; ++bq) r.terms.push_back({10 * bf.cell + entryIndex(iv, bq), 2.0 * Wt.row(bq).head<3>().dot(nu)});
      r.rhs = lmid;
      rows.push_back(r);
    }
  }
}

void internalFaceRows(const std::vector<Tetrahedron>& cells, std::vector<Row>& rows) {
  const int n = int(cells.size());
  // G1 (3.23) across every internal face.
  for (int s = 0; s < n; ++s)
    for (int t = s + 1; t < n; ++t) {
      const Tetrahedron &S = cells[std::size_t(s)], &T = cells[std::size_t(t)];
      if (!sharesFace(S, T)) continue;
      const SharedFace f = findSharedFace(S, T);
      BBQuadric probe(S, Eigen::Matrix4d::Zero());
      const Vector4d lam = probe.barycentric(T[std::size_t(f.free_b)]);
      for (int i = 0; i < 3; ++i) {
        for (int j = i; j < 3; ++j)
          rows.push_back({{{10 * t + entryIndex(f.b[i], f.b[j]), 1.0}, {10 * s + entryIndex(f.a[i], f.a[j]), -1.0}}, 0.0});
        Row r;
        r.terms.push_back({10 * t + entryIndex(f.b[i], f.free_b), 1.0});
        for (int j = 0; j < 4; ++j) r.terms.push_back({10 * s + entryIndex(f.a[i], j), -lam[j]});
        rows.push_back(r);
      }
    }
}

// The constraints' solutions: a particular one (least squares, refused when the residual
// shows them inconsistent) and a basis of their null space.
struct ConstraintSolution {
  VectorXd xp;
  MatrixXd N;
};

ConstraintSolution solveConstraints(const std::vector<Row>& rows, int unknowns, int patch, const MacropatchOptions& o) {
  MatrixXd B = MatrixXd::Zero(Eigen::Index(rows.size()), unknowns);
  VectorXd d(Eigen::Index(rows.size()));
  for (std::size_t r = 0; r < rows.size(); ++r) {
    for (const auto& tm : rows[r].terms) B(Eigen::Index(r), tm.first) += tm.second;
    d[Eigen::Index(r)] = rows[r].rhs;
  }
  Eigen::BDCSVD<MatrixXd> svd(B, Eigen::ComputeFullV | Eigen::ComputeThinU);
  const double smax = svd.singularValues()[0];
  svd.setThreshold(1e-10);
  const int rank = int(svd.rank());
  const VectorXd xp = svd.solve(d);
  const double residual = (B * xp - d).norm() / std::max(1.0, d.norm());
  if (!(residual < 1e-8))
    throw std::invalid_argument("macropatch: the G1 constraints of control net " + std::to_string(patch) +
                                " are inconsistent (residual " + std::to_string(residual) + ")" +
                                (o.cross_boundary ? "; this net does not admit G1 between macropatches, use G0 joins between them"
                                                  : ""));
  (void)smax;
  return {xp, svd.matrixV().rightCols(unknowns - rank)};

}

// Fit rows: the Bézier triangle's points and tangents.
std::vector<Row> fitRows(const ControlNet& P, const std::vector<Tetrahedron>& cells, const MacropatchOptions& o) {
  const int n = int(cells.size());
  std::vector<Eigen::Matrix4d> W(static_cast<std::size_t>(n));  // λ = W X
  for (int t = 0; t < n; ++t) W[std::size_t(t)] = BBQuadric::vertexMatrix(cells[std::size_t(t)]).transpose().inverse();
  std::vector<Row> fit;
  for (const TriangleSample& s : triangleSamples(P, W, o.fit_samples)) {
    const int best = int(s.cell);
    const Vector4d& lam = s.lambda;
    const Eigen::Matrix4d& Wt = W[s.cell];
    Row f;
    for (int a = 0; a < 4; ++a)
      for (int b = a; b < 4; ++b)
        f.terms.push_back({10 * best + entryIndex(a, b), (a == b ? 1.0 : 2.0) * lam[a] * lam[b]});
    fit.push_back(f);
    for (const Vector3d& tv : s.tangents) {
      Row g;
      for (int a = 0; a < 4; ++a)
        for (int b = a; b < 4; ++b) {
          const double da = Wt.row(a).head<3>().dot(tv), db = Wt.row(b).head<3>().dot(tv);
          const double c = a == b ? 2.0 * lam[a] * da : 2.0 * (lam[b] * da + lam[a] * db);
          g.terms.push_back({10 * best + entryIndex(a, b), o.normal_weight * c});
        }
      fit.push_back(g);
    }
  }
  return fit;
}

// The solution closest to the fit rows (ridge-regularised) among xp + N y.
VectorXd fitInNullSpace(const std::vector<Row>& fit, const ConstraintSolution& c, int unknowns,
                        const MacropatchOptions& o) {
  const VectorXd& xp = c.xp;
  const MatrixXd& N = c.N;
  MatrixXd F = MatrixXd::Zero(Eigen::Index(fit.size()), unknowns);
  for (std::size_t r = 0; r < fit.size(); ++r)
    for (const auto& tm : fit[r].terms) F(Eigen::Index(r), tm.first) += tm.second;
  VectorXd x = xp;
  if (N.cols() > 0) {
    const MatrixXd FN = F * N;
    MatrixXd H = FN.transpose() * FN;
    const double ridge = o.ridge * std::max(1.0, H.diagonal().maxCoeff());
    H.diagonal().array() += ridge;
    const VectorXd rhs = -FN.transpose() * (F * xp) - ridge * (N.transpose() * xp);
    x += N * H.ldlt().solve(rhs);
  }
  return x;
}

void buildG1(const ControlNet& P, int patch, const std::map<Key, CornerData>& corners, const MacropatchOptions& o,
             std::vector<MacropatchCell>& out) {
  const G1Cells g = g1Cells(P);
  const std::vector<Tetrahedron>& cells = g.cells;
  const int n = int(cells.size()), unknowns = 10 * n;
  std::vector<Row> rows;
  cornerRows(P, cells, corners, rows);
  boundaryRows(g, corners, o, rows);
  internalFaceRows(cells, rows);
  const ConstraintSolution c = solveConstraints(rows, unknowns, patch, o);
  const VectorXd x = fitInNullSpace(fitRows(P, cells, o), c, unknowns, o);

  for (int t = 0; t < n; ++t) {
    MacropatchCell c;
    c.patch = patch;
    c.bb.V = cells[std::size_t(t)];
    for (int a = 0; a < 4; ++a)
      for (int b = 0; b < 4; ++b) c.bb.C(a, b) = x[10 * t + entryIndex(a, b)];
    out.push_back(c);
  }
}

}  // namespace

Vector3d bezierTrianglePoint(const ControlNet& P, double u, double v, double w) {
  return u * u * P[0] + v * v * P[2] + w * w * P[4] + 2 * u * v * P[1] + 2 * v * w * P[3] + 2 * w * u * P[5];
}

Vector3d bezierTriangleNormal(const ControlNet& P, double u, double v, double w) {
  const std::array<Vector3d, 2> t = bezierTriangleTangents(P, u, v, w);
  Vector3d n = t[0].cross(t[1]);
  const Vector3d outward = (P[1] + P[3] + P[5]) / 3.0 - (P[0] + P[2] + P[4]) / 3.0;
  if (n.dot(outward) < 0) n = -n;
  return n;
}

std::vector<MacropatchCell> buildMacropatchCells(const std::vector<ControlNet>& nets, const MacropatchOptions& options) {
  // The systems are small (~350 x 180): Eigen's OpenMP-parallel products only add
  // synchronisation cost (seconds on a loaded machine), so run them on this thread.
  struct SingleThreadedEigen {
    int saved = Eigen::nbThreads();
    SingleThreadedEigen() { Eigen::setNbThreads(1); }
    ~SingleThreadedEigen() { Eigen::setNbThreads(saved); }
  } single_threaded;
  std::vector<MacropatchCell> out;
  for (const auto& net : nets) checkNet(net);
  if (options.model == MacropatchModel::G0) {
    if (options.apex < 0 || options.corner_apex < 0 || options.control_apex < 0)
      throw std::invalid_argument("macropatch: G0 apex coefficients must be >= 0 (else the surface leaves its cells)");
    for (std::size_t i = 0; i < nets.size(); ++i)
      buildG0(nets[i], int(i), options.fit_g0 ? fitG0Constants(nets[i], options) : options, out);
  } else {
    const auto corners = cornerData(nets);
    for (std::size_t i = 0; i < nets.size(); ++i) buildG1(nets[i], int(i), corners, options, out);
  }
  return out;
}

std::vector<Primitive> macropatchPrimitives(const std::vector<MacropatchCell>& cells, int material, int object,
                                            const ViewVolume* view, ViewCullCount* count) {
  ViewCullCount local(view != nullptr);
  ViewCullCount& seen = count ? *count : local;
  std::vector<Primitive> out;
  for (const auto& c : cells) {
    // The piece is clipped by the cell's four faces: it lies in the tetrahedron.
    if (view && !seen.keep(view->mayContain(c.bb.V.data(), c.bb.V.size()))) continue;
    if (!c.bb.isProvablyEmpty()) out.push_back(c.bb.toPrimitive(material, object, false));
  }
  return out;
}

MacropatchContinuity measureMacropatchContinuity(const std::vector<MacropatchCell>& cells, int subdivisions) {
  MacropatchContinuity r;
  std::vector<Quadric> q;
  for (const auto& c : cells) q.push_back(c.bb.toQuadric());
  for (std::size_t s = 0; s < cells.size(); ++s)
    for (std::size_t t = s + 1; t < cells.size(); ++t) {
      if (!sharesFace(cells[s].bb.V, cells[t].bb.V)) continue;
      const SharedFace f = findSharedFace(cells[s].bb.V, cells[t].bb.V);
      const auto& V = cells[s].bb.V;
      const FaceContinuity fc = measureFaceContinuity(q[s], q[t], V[std::size_t(f.a[0])], V[std::size_t(f.a[1])],
                                                      V[std::size_t(f.a[2])], subdivisions);
      if (cells[s].patch == cells[t].patch) {
        mergeContinuity(r.internal, fc);
        ++r.internal_faces;
      } else {
        mergeContinuity(r.external, fc);
        ++r.external_faces;
      }
    }
  return r;
}

std::vector<ControlNet> namedControlNets(const std::string& name, double radius) {
  if (name != "octahedron") throw std::invalid_argument("unknown control net surface '" + name + "' (known: octahedron)");
  std::vector<ControlNet> nets;
  for (int sx : {1, -1})
    for (int sy : {1, -1})
      for (int sz : {1, -1}) {
        const double x = radius * sx, y = radius * sy, z = radius * sz;
        nets.push_back({Vector3d(x, 0, 0), Vector3d(x, y, 0), Vector3d(0, y, 0), Vector3d(0, y, z),
                        Vector3d(0, 0, z), Vector3d(x, 0, z)});
      }
  return nets;
}

BezierMesh tessellateBezierTriangles(const std::vector<ControlNet>& nets, int n) {
  if (n < 1) throw std::invalid_argument("tessellation level must be >= 1");
  BezierMesh mesh;
  std::map<std::array<long long, 3>, int> index;
  auto vertex = [&](const Vector3d& p) {
    std::array<long long, 3> key;
    for (int i = 0; i < 3; ++i) key[std::size_t(i)] = std::llround(p[i] * 1e9);
    auto it = index.find(key);
    if (it != index.end()) return it->second;
    const int id = int(mesh.vertices.size());
    mesh.vertices.push_back(p);
    index.emplace(key, id);
    return id;
  };
  for (const auto& net : nets) {
    std::vector<std::vector<int>> id(std::size_t(n + 1));
    for (int i = 0; i <= n; ++i)
      for (int j = 0; i + j <= n; ++j) {
        const double u = double(i) / n, v = double(j) / n;
        id[std::size_t(i)].push_back(vertex(bezierTrianglePoint(net, u, v, 1.0 - u - v)));
      }
    // Orient triangles so their winding normal agrees with bezierTriangleNormal.
    const Vector3d ref = bezierTriangleNormal(net, 1.0 / 3, 1.0 / 3, 1.0 / 3);
    const Vector3d p0 = bezierTrianglePoint(net, 0, 0, 1), pu = bezierTrianglePoint(net, 1, 0, 0),
                   pv = bezierTrianglePoint(net, 0, 1, 0);
    const bool flip = (pu - p0).cross(pv - p0).dot(ref) < 0;
    auto tri = [&](int a, int b, int c) {
      if (flip) std::swap(b, c);
      mesh.triangles.push_back({a, b, c});
    };
    for (int i = 0; i < n; ++i)
      for (int j = 0; i + j < n; ++j) {
        tri(id[std::size_t(i)][std::size_t(j)], id[std::size_t(i + 1)][std::size_t(j)], id[std::size_t(i)][std::size_t(j + 1)]);
        if (i + j + 1 < n)
          tri(id[std::size_t(i + 1)][std::size_t(j)], id[std::size_t(i + 1)][std::size_t(j + 1)], id[std::size_t(i)][std::size_t(j + 1)]);
      }
  }
  return mesh;
}

std::vector<Primitive> buildMacropatch(const JsonNode& o, ObjectContext& ctx) {
  if (ctx.solid)
    o.at("solid").fail("macropatch cells are surface pieces; caps on their cell faces would show the cells, not a solid");
  std::vector<ControlNet> nets;
  const auto netsNode = o.get("control_nets");
  const auto surfNode = o.get("surface");
  if (netsNode && surfNode) surfNode->fail("give either \"control_nets\" or \"surface\", not both");
  if (!netsNode && !surfNode) o.fail("a macropatch needs \"control_nets\" or \"surface\"");
  if (netsNode) {
    if (netsNode->size() == 0) netsNode->fail("expected at least one control net");
    for (std::size_t i = 0; i < netsNode->size(); ++i) {
      const JsonNode net = (*netsNode)[i];
      if (net.size() != 6) net.fail("a control net has exactly 6 points (P1..P6)");
      ControlNet cn;
      for (std::size_t k = 0; k < 6; ++k) cn[k] = net[k].vec3();
      nets.push_back(cn);
    }
  } else {
    const double r = o.positive("radius", 1.0);
    try {
      nets = namedControlNets(surfNode->string(), r);
    } catch (const std::invalid_argument& e) {
      surfNode->fail(e.what());
    }
  }
  MacropatchOptions opt;
  const std::string model = o.string("model", "G0");
  if (model == "bezier") {
    // The same control nets as quadratic Bézier triangles, tessellated (for comparisons).
    const int n = int(o.has("tessellation") ? o.at("tessellation").integer(1, 256) : 8);
    const BezierMesh mesh = tessellateBezierTriangles(nets, n);
    ViewCullCount seen(ctx.view != nullptr);
    std::vector<Primitive> tris;
    for (const auto& t : mesh.triangles) {
      const Vector3d &a = mesh.vertices[std::size_t(t[0])], &b = mesh.vertices[std::size_t(t[1])],
                     &c = mesh.vertices[std::size_t(t[2])];
      if (!((b - a).cross(c - a).norm() > 0)) continue;
      const Vector3d corners[3] = {a, b, c};
      if (ctx.view && !seen.keep(ctx.view->mayContain(corners, 3))) continue;
      tris.push_back(makeTriangle(a, b, c));
    }
    ctx.note = seen.note();
    return tris;
  }
  if (o.has("tessellation")) o.at("tessellation").fail("only the \"bezier\" model is tessellated");
  if (model == "G0") opt.model = MacropatchModel::G0;
  else if (model == "G1") opt.model = MacropatchModel::G1;
  else o.at("model").fail("expected \"G0\" (4 quadrics per net), \"G1\" (18 quadrics per net) or \"bezier\" (triangles)");
  if (opt.model == MacropatchModel::G1) {
    const std::string between = o.string("between", "G1");
    if (between == "G1") opt.cross_boundary = true;
    else if (between == "G0") opt.cross_boundary = false;
    else o.at("between").fail("expected \"G1\" or \"G0\" (continuity between macropatches)");
  } else if (o.has("between")) {
    o.at("between").fail("the G0 model joins macropatches with G0 only");
  }
  if (opt.model == MacropatchModel::G0) {
    opt.fit_g0 = !(o.has("apex") || o.has("corner_apex") || o.has("control_apex"));
    opt.apex = o.number("apex", opt.apex);
    opt.corner_apex = o.number("corner_apex", opt.corner_apex);
    opt.control_apex = o.number("control_apex", opt.control_apex);
  } else {
    for (const char* key : {"apex", "corner_apex", "control_apex"})
      if (o.has(key)) o.at(key).fail("only the G0 model has user-set constants");
  }
  try {
    ViewCullCount seen(ctx.view != nullptr);
    std::vector<Primitive> prims = macropatchPrimitives(buildMacropatchCells(nets, opt), ctx.material, 0, ctx.view, &seen);
    ctx.note = seen.note();
    return prims;
  } catch (const std::invalid_argument& e) {
    (netsNode ? *netsNode : *surfNode).fail(e.what());
  }
}

namespace {
// The scene object type this modeler provides (loader/object_registry.h).
[[maybe_unused]] const bool kRegistered = registerObjectTypes({
    {"macropatch", buildMacropatch},
});

}  // namespace

}  // namespace qacc
