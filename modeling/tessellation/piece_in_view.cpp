// Whether a tessellated piece surely reaches the view (piece_in_view.h).
#include "modeling/tessellation/piece_in_view.h"

#include <cmath>

#include "modeling/tessellation/surface_clipping.h"

namespace qacc::tess {

namespace {

// Inside every clip half-space of the piece, up to the rounding of the cut points (a vertex on
// a clip plane is found by bisection or Newton steps, so it may lie a rounding error beyond).
bool insideClipRegion(const Primitive& prim, const Vector3d& x) {
  for (const HalfSpace& h : prim.clip) {
    const double tol = 1e-9 * (h.p.head<3>().norm() * x.norm() + std::abs(h.p[3]));
    if (!(h.eval(x) <= tol)) return false;
  }
  return true;
}

}  // namespace

PieceInView::PieceInView(const ScreenView& view) : view_(view) {
  // Window x = (W X)_0 / (W X)_3 and so on; 0 <= x <= width is -row0 <= 0 and
  // row0 - width row3 <= 0 (their conjunction implies a positive weight).
  const Eigen::Matrix4d& W = view.window;
  const Eigen::Vector4d x = W.row(0).transpose(), y = W.row(1).transpose(), z = W.row(2).transpose(),
                        w = W.row(3).transpose();
  for (const Eigen::Vector4d& p : {Eigen::Vector4d(-x), Eigen::Vector4d(x - view.width * w), Eigen::Vector4d(-y),
                                   Eigen::Vector4d(y - view.height * w), Eigen::Vector4d(-z), Eigen::Vector4d(z - w)})
    image_.emplace_back(p);
}

bool PieceInView::surelyInView(const Primitive& prim, const TriangleMesh3& mesh, std::size_t surfaceTriangles) const {
  const std::size_t n = std::min(surfaceTriangles, mesh.triangles.size());
  const Quadric q = prim.quadric.normalized();
  // On the quadric up to rounding: a surface vertex of the tessellation is not always (a piece
  // tessellated into triangles across the screen has vertices far from its surface).
  auto onSurface = [&](const Vector3d& s) {
    return s.allFinite() && std::abs(q.eval(s)) <= 1e-9 * q.gradient(s).norm() * (1.0 + s.norm());
  };
  auto inView = [&](const Vector3d& x) {
    return view_.onScreen(x, kInViewMarginPixels) && insideClipRegion(prim, x) && onSurface(x);
  };
  for (std::size_t t = 0; t < n; ++t)
    for (int k = 0; k < 3; ++k)
      if (inView(mesh.positions[std::size_t(mesh.triangles[t][std::size_t(k)])])) return true;
  Domain world;
  world.linear = true;
  world.position = [](const Vector3d& p) { return p; };
  Polygon tri, scratch;
  for (std::size_t t = 0; t < n; ++t) {
    tri.assign(3, ClipVertex{});
    for (int k = 0; k < 3; ++k) {
      ClipVertex& v = tri[std::size_t(k)];
      v.coord = mesh.positions[std::size_t(mesh.triangles[t][std::size_t(k)])];
      v.pos = v.coord;  // the domain is world space
    }
    // Quick rejection: all three corners beyond one side of the image.
    bool outside = false;
    for (const HalfSpace& h : image_) {
      bool all = true;
      for (const ClipVertex& v : tri) all = all && h.eval(v.coord) > 0;
      outside = outside || all;
    }
    if (outside) continue;
    clipPolygon(tri, scratch, world, image_);
    const Polygon& part = tri;
    if (part.empty()) continue;
    Vector3d centroid = Vector3d::Zero();
    for (const ClipVertex& v : part) centroid += v.coord;
    centroid /= double(part.size());
    // The centroid, then the part's corners (on the image's border or the triangle's corners)
    // drawn a tenth of the way towards it.
    std::vector<Vector3d> tries{centroid};
    for (const ClipVertex& v : part) tries.push_back(v.coord + 0.1 * (centroid - v.coord));
    for (const Vector3d& x : tries) {
      if (inView(closestPointOnQuadric(q, x))) return true;
    }
  }
  return false;
}

}  // namespace qacc::tess
