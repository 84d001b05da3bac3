#include "modeling/tessellation/marching_piece.h"

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <unordered_map>

#include "modeling/algebraic/marching_tetrahedra.h"
#include "modeling/tessellation/screen_error.h"

namespace qacc::tess {

// The part of `box` where the surface can be: the cells of a 40³ scan whose corners change
// sign (or come within a cell's gradient bound of zero), inside the clip planes' reach. Only
// the bounding box of those cells is wanted, and it is found with a fraction of the work of
// testing every cell, with the same result: the scan runs by blocks of 8³ cells, and a block
// is skipped when it lies inside the box found so far, when a bound of the quadric over it
// (value, gradient and curvature at its centre) keeps every corner beyond the margin, or when
// every cell centre in it is beyond a plane's reach; the quadric is evaluated at a grid point
// only when a cell looked at needs it.
Eigen::AlignedBox3d surfaceBox(const Quadric& q, const Eigen::AlignedBox3d& box, const std::vector<HalfSpace>& planes) {
  constexpr int n = 40, block = 8;
  const Vector3d h = box.sizes() / n;
  Eigen::AlignedBox3d out;
  // The values found so far, per thread and kept across calls: a value is this call's when
  // its stamp is this call's (no 41³ clear, no fresh pages, per call).
  constexpr std::size_t points = std::size_t(n + 1) * (n + 1) * (n + 1);
  thread_local std::vector<double> val(points);
  thread_local std::vector<std::uint32_t> stamp(points, 0);
  thread_local std::uint32_t call = 0;
  if (++call == 0) {  // the stamps wrapped: start again
    std::fill(stamp.begin(), stamp.end(), 0u);
    call = 1;
  }
  auto pt = [&](int i, int j, int k) { return Vector3d(box.min() + h.cwiseProduct(Vector3d(i, j, k))); };
  auto at = [&](int i, int j, int k) {
    const std::size_t m = (std::size_t(k) * (n + 1) + j) * (n + 1) + i;
    if (stamp[m] != call) {
      val[m] = q.eval(pt(i, j, k));
      stamp[m] = call;
    }
    return val[m];
  };
  // A quadric can dip between corners: allow a margin of one cell's curvature.
  const Matrix3d absA = q.Q.topLeftCorner<3, 3>().cwiseAbs();
  const double margin = 2.0 * (absA * h.cwiseAbs()).dot(h.cwiseAbs());
  std::vector<double> reach;  // a cell centre beyond a plane by more than this is out
  for (const auto& pl : planes) reach.push_back(0.5 * pl.p.head<3>().cwiseAbs().dot(h) + 1e-12);
  // Cells spanned by `out` so far (empty: none).
  Eigen::Vector3i lo(n, n, n), hi(-1, -1, -1);
  auto covered = [&](const Eigen::Vector3i& a, const Eigen::Vector3i& b) {
    return (a.array() >= lo.array()).all() && (b.array() <= hi.array()).all();
  };
  auto cell = [&](int i, int j, int k) {
    if (covered({i, j, k}, {i, j, k})) return;
    double vlo = 1e300, vhi = -1e300;
    for (int c = 0; c < 8; ++c) {
      const double v = at(i + (c & 1), j + ((c >> 1) & 1), k + ((c >> 2) & 1));
      vlo = std::min(vlo, v);
      vhi = std::max(vhi, v);
    }
    if (vlo > margin || vhi < -margin) return;
    const Vector3d centre = pt(i, j, k) + 0.5 * h;
    for (std::size_t p = 0; p < planes.size(); ++p)
      if (planes[p].eval(centre) > reach[p]) return;
    out.extend(pt(i, j, k));
    out.extend(pt(i + 1, j + 1, k + 1));
    lo = lo.cwiseMin(Eigen::Vector3i(i, j, k));
    hi = hi.cwiseMax(Eigen::Vector3i(i, j, k));
  };
  for (int bk = 0; bk < n; bk += block)
    for (int bj = 0; bj < n; bj += block)
      for (int bi = 0; bi < n; bi += block) {
        const Eigen::Vector3i b0(bi, bj, bk), b1(bi + block - 1, bj + block - 1, bk + block - 1);
        if (covered(b0, b1)) continue;
        // The block's corners are the grid points b0 .. b1 + 1; its centre c, half-size r.
        const Vector3d c = 0.5 * (pt(bi, bj, bk) + pt(bi + block, bj + block, bk + block));
        const Vector3d r = 0.5 * block * h.cwiseAbs();
        const double fc = q.eval(c);
        const double spread = q.gradient(c).cwiseAbs().dot(r) + (absA * r).dot(r);
        const double slack = 1e-9 * (std::fabs(fc) + spread + margin);
        if (fc - spread > margin + slack || fc + spread < -margin - slack) continue;
        bool beyond = false;  // every cell centre of the block beyond one plane's reach
        const Vector3d rc = r - 0.5 * h.cwiseAbs();
        for (std::size_t p = 0; p < planes.size() && !beyond; ++p) {
          const double e = planes[p].eval(c), s = planes[p].p.head<3>().cwiseAbs().dot(rc);
          beyond = e - s > reach[p] + 1e-9 * (std::fabs(e) + s);
        }
        if (beyond) continue;
        for (int k = bk; k <= b1.z(); ++k)
          for (int j = bj; j <= b1.y(); ++j)
            for (int i = bi; i <= b1.x(); ++i) cell(i, j, k);
      }
  return out.isEmpty() ? box : out;
}

// Marching tetrahedra (marchKuhnGrid) over `box` with about n cells along the longest side;
// edge points start at the linear interpolation and take Newton steps onto the quadric.
void marchQuadricBox(SurfaceBuilder& sb, const Quadric& q, const Eigen::AlignedBox3d& box0, int n) {
  // Padded by a cell and a half: the marching mesh's own boundary (on the box faces, its
  // vertices then moved by Newton steps) must lie beyond the clip planes, which cut it.
  Eigen::AlignedBox3d box = box0;
  const Vector3d pad = Vector3d::Constant(1.5 * box.sizes().maxCoeff() / std::max(1, n) + 1e-9);
  box.extend(box.max() + pad);
  box.extend(box.min() - pad);
  const double h = box0.sizes().maxCoeff() / std::max(1, n);  // the cell of the unpadded box
  Eigen::Vector3i dims;
  for (int a = 0; a < 3; ++a) dims[a] = std::max(1, int(std::ceil(box.sizes()[a] / h - 1e-9)));
  auto point = [&](const Eigen::Vector3i& c) { return Vector3d(box.min() + h * c.cast<double>()); };
  // The grid's values and the edge points, per thread and kept across calls (a piece's
  // marching makes no large allocation once its thread has marched a piece as large).
  thread_local std::vector<double> val;
  val.resize(std::size_t((dims[0] + 1)) * (dims[1] + 1) * (dims[2] + 1));
  std::size_t at = 0;
  for (int k = 0; k <= dims[2]; ++k)
    for (int j = 0; j <= dims[1]; ++j)
      for (int i = 0; i <= dims[0]; ++i) {
        double v = q.eval(point({i, j, k}));
        if (v == 0) v = 1e-300;  // grid points never exactly on the surface
        val[at++] = v;
      }
  thread_local std::unordered_map<std::uint64_t, Vector3d> edgeCache;
  edgeCache.clear();
  const std::uint64_t npoints = val.size();
  auto E = [&](const KuhnEdge& e) {
    const std::uint64_t key = std::uint64_t(e.ia) * npoints + std::uint64_t(e.ib);  // exact pair key
    auto it = edgeCache.find(key);
    if (it != edgeCache.end()) return it->second;
    const Vector3d pa = point(e.a), pb = point(e.b);
    const double fa = val[std::size_t(e.ia)], fb = val[std::size_t(e.ib)];
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
  KuhnCrossings crossings;
  crossings.triangle = [&](const KuhnEdge& e0, const KuhnEdge& e1, const KuhnEdge& e2) {
    sb.addTriangle(E(e0), E(e1), E(e2));
  };
  crossings.quad = [&](const KuhnEdge& e0, const KuhnEdge& e1, const KuhnEdge& e2, const KuhnEdge& e3) {
    sb.addQuad(E(e0), E(e1), E(e2), E(e3));
  };
  marchKuhnGrid(dims, val, crossings);
}

void marchQuadricPiece(SurfaceBuilder& sb, const Quadric& q, const Eigen::AlignedBox3d& box,
                       const std::vector<HalfSpace>& planes, int target) {
  const int n = std::max(4, int(std::lround(std::sqrt(std::max(2, target) / 3.0))));
  marchQuadricBox(sb, q, surfaceBox(q, box, planes), n);
}

int marchingCellsForPixelError(const Quadric& q, const Eigen::AlignedBox3d& box, const std::vector<HalfSpace>& planes,
                               const ScreenView& view, double epsilon, double scale, int max_triangles) {
  constexpr int kCoarse = 8;
  constexpr int kMaxCells = 128;  // the value grid is (n + 1)³ doubles: 17 MB
  TriangleMesh3 probe;
  CapSegments caps;
  Domain identity;
  identity.linear = true;
  identity.position = [](const Vector3d& p) { return p; };
  SurfaceBuilder sb{q, identity, planes, 0, probe, caps};
  marchQuadricBox(sb, q, box, kCoarse);
  const Matrix3d H = 2.0 * q.Q.topLeftCorner<3, 3>();
  const double margin = 0.1 * std::max(view.width, view.height);
  double aSeen = 0, aAll = 0;
  for (const Vector3d& p : probe.positions) {
    const Vector3d g = q.gradient(p);
    const double gn = g.norm();
    if (!(gn > 1e-12 * (1 + p.norm())) || !view.inFront(p)) continue;
    const Vector3d n = g / gn;
    const Matrix3d P = Matrix3d::Identity() - n * n.transpose();
    const Matrix3d T = P * H * P / gn;  // shape operator: the principal curvatures and 0
    const double kappa = Eigen::SelfAdjointEigenSolver<Matrix3d>(T, Eigen::EigenvaluesOnly).eigenvalues().cwiseAbs().maxCoeff();
    const double a = view.pixelsPerUnit(p) * kappa;
    aAll = std::max(aAll, a);
    if (view.onScreen(p, margin)) aSeen = std::max(aSeen, a);
  }
  const double A = aSeen > 0 ? aSeen : aAll;
  if (!(A > 0)) return kCoarse;  // flat: the coarse cells are exact
  const double h = std::sqrt(2.0 * 0.8 * epsilon / A) / scale;
  const double side = box.sizes().maxCoeff();
  double n = std::ceil(side / h);
  // The surface crosses about (triangles of the probe) (n / kCoarse)² cells; keep that in budget.
  const double perCell = std::max<double>(1.0, double(probe.size())) / (kCoarse * kCoarse);
  n = std::min(n, std::sqrt(std::max(1, max_triangles) / perCell));
  return int(std::clamp(n, 4.0, double(kMaxCells)));
}

}  // namespace qacc::tess
