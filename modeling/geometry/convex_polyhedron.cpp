#include "modeling/geometry/convex_polyhedron.h"

#include <algorithm>
#include <cmath>

namespace qacc {
namespace {

using Vec = Eigen::Vector3d;

double value(const Eigen::Vector4d& unit, const Vec& x) { return unit.head<3>().dot(x) + unit.w(); }

bool has(const std::vector<int>& sorted, int id) { return std::binary_search(sorted.begin(), sorted.end(), id); }

void insertSorted(std::vector<int>& sorted, int id) {
  const auto it = std::lower_bound(sorted.begin(), sorted.end(), id);
  if (it == sorted.end() || *it != id) sorted.insert(it, id);
}

// The planes two sorted lists share.
std::vector<int> common(const std::vector<int>& a, const std::vector<int>& b) {
  std::vector<int> out;
  std::set_intersection(a.begin(), a.end(), b.begin(), b.end(), std::back_inserter(out));
  return out;
}

int countCommon(const std::vector<int>& a, const std::vector<int>& b) {
  int n = 0;
  for (std::size_t i = 0, j = 0; i < a.size() && j < b.size();) {
    if (a[i] < b[j]) {
      ++i;
    } else if (b[j] < a[i]) {
      ++j;
    } else {
      ++n, ++i, ++j;
    }
  }
  return n;
}

}  // namespace

ConvexPolyhedron ConvexPolyhedron::tetrahedron(const std::array<Vec, 4>& x, const std::array<int, 4>& plane,
                                               const std::array<bool, 4>& flip) {
  ConvexPolyhedron p;
  for (int a = 0; a < 4; ++a) {
    Vertex v{x[std::size_t(a)], {}};
    for (int b = 0; b < 4; ++b)
      if (b != a) v.planes.push_back(plane[std::size_t(b)]);
    std::sort(v.planes.begin(), v.planes.end());
    p.verts_.push_back(std::move(v));
    p.faces_.push_back(Face{plane[std::size_t(a)], flip[std::size_t(a)]});
  }
  return p;
}

Eigen::AlignedBox3d ConvexPolyhedron::box() const {
  Eigen::AlignedBox3d b;
  for (const Vertex& v : verts_) b.extend(v.x);
  return b;
}

Vec ConvexPolyhedron::centroid() const {
  Vec c = Vec::Zero();
  for (const Vertex& v : verts_) c += v.x;
  return c / double(verts_.size());
}

void ConvexPolyhedron::sides(const Eigen::Vector4d& unit, double eps, bool& neg, bool& pos) const {
  neg = pos = false;
  for (const Vertex& v : verts_) {
    const double s = value(unit, v.x);
    neg = neg || s < -eps;
    pos = pos || s > eps;
    if (neg && pos) return;
  }
}

void ConvexPolyhedron::keepFaces(const std::vector<Face>& candidates) {
  faces_.clear();
  for (const Face& f : candidates) {
    int on = 0;
    for (const Vertex& v : verts_) on += has(v.planes, f.plane);
    if (on >= 3) faces_.push_back(f);
  }
}

bool ConvexPolyhedron::split(int id, const std::vector<Eigen::Vector4d>& unit, double eps, ConvexPolyhedron& neg,
                             ConvexPolyhedron& pos) const {
  const Eigen::Vector4d& h = unit[std::size_t(id)];
  std::vector<double> s(verts_.size());
  bool anyNeg = false, anyPos = false;
  for (std::size_t i = 0; i < verts_.size(); ++i) {
    s[i] = value(h, verts_[i].x);
    anyNeg = anyNeg || s[i] < -eps;
    anyPos = anyPos || s[i] > eps;
  }
  if (!anyNeg || !anyPos) return false;
  ConvexPolyhedron a, b;
  for (std::size_t i = 0; i < verts_.size(); ++i) {
    if (s[i] < -eps) {
      a.verts_.push_back(verts_[i]);
    } else if (s[i] > eps) {
      b.verts_.push_back(verts_[i]);
    } else {
      Vertex v = verts_[i];
      insertSorted(v.planes, id);
      a.verts_.push_back(v);
      b.verts_.push_back(std::move(v));
    }
  }
  for (std::size_t i = 0; i < verts_.size(); ++i) {
    if (!(s[i] < -eps)) continue;
    for (std::size_t j = 0; j < verts_.size(); ++j) {
      if (!(s[j] > eps) || countCommon(verts_[i].planes, verts_[j].planes) < 2) continue;
      Vertex v{verts_[i].x + (verts_[j].x - verts_[i].x) * (s[i] / (s[i] - s[j])),
               common(verts_[i].planes, verts_[j].planes)};
      insertSorted(v.planes, id);
      a.verts_.push_back(v);
      b.verts_.push_back(std::move(v));
    }
  }
  std::vector<Face> fa = faces_, fb = faces_;
  fa.push_back(Face{id, false});
  fb.push_back(Face{id, true});
  a.keepFaces(fa);
  b.keepFaces(fb);
  neg = std::move(a);
  pos = std::move(b);
  return true;
}

ConvexPolyhedron ConvexPolyhedron::clipped(int id, bool flip, const std::vector<Eigen::Vector4d>& unit,
                                           double eps) const {
  bool neg, pos;
  sides(unit[std::size_t(id)], eps, neg, pos);
  const bool keepsAll = flip ? !neg : !pos, keepsNone = flip ? !pos : !neg;
  if (keepsNone) return ConvexPolyhedron();
  if (keepsAll) return *this;
  ConvexPolyhedron a, b;
  split(id, unit, eps, a, b);
  return flip ? b : a;
}

bool ConvexPolyhedron::crossedBy(const Vec& a, const Vec& b, const Vec& c, const std::vector<Eigen::Vector4d>& unit,
                                 double eps) const {
  std::vector<Vec> poly = {a, b, c}, next;
  for (const Face& f : faces_) {
    const Eigen::Vector4d h = f.flip ? Eigen::Vector4d(-unit[std::size_t(f.plane)]) : unit[std::size_t(f.plane)];
    next.clear();
    for (std::size_t i = 0; i < poly.size(); ++i) {
      const Vec& p = poly[i];
      const Vec& q = poly[(i + 1) % poly.size()];
      const double vp = value(h, p), vq = value(h, q);
      const bool ip = vp <= -eps, iq = vq <= -eps;  // strictly inside, with a margin
      if (ip) next.push_back(p);
      if (ip != iq) next.push_back(p + (q - p) * std::clamp((vp + eps) / (vp - vq), 0.0, 1.0));
    }
    poly.swap(next);
    if (poly.size() < 3) return false;
  }
  double area = 0;
  for (std::size_t i = 1; i + 1 < poly.size(); ++i) area += (poly[i] - poly[0]).cross(poly[i + 1] - poly[0]).norm();
  return area > 1e3 * eps * eps;
}

std::vector<std::array<Vec, 4>> ConvexPolyhedron::fan(const std::vector<Eigen::Vector4d>& unit) const {
  std::vector<std::array<Vec, 4>> out;
  const Vec apex = centroid();
  for (const Face& f : faces_) {
    std::vector<Vec> ring;
    for (const Vertex& v : verts_)
      if (has(v.planes, f.plane)) ring.push_back(v.x);
    Vec m = Vec::Zero();
    for (const Vec& p : ring) m += p / double(ring.size());
    // Order the face's vertices by angle about its centre, in the plane's own 2D frame.
    const Vec n = unit[std::size_t(f.plane)].head<3>();
    const Vec e1 = (ring[0] - m).normalized(), e2 = n.cross(e1);
    std::sort(ring.begin(), ring.end(), [&](const Vec& p, const Vec& q) {
      return std::atan2((p - m).dot(e2), (p - m).dot(e1)) < std::atan2((q - m).dot(e2), (q - m).dot(e1));
    });
    for (std::size_t i = 1; i + 1 < ring.size(); ++i) out.push_back({apex, ring[0], ring[i], ring[i + 1]});
  }
  return out;
}

}  // namespace qacc
