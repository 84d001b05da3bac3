// The builder of one primitive's surface triangles (a triangle soup, one normal per corner,
// the quadric's gradient): domain polygons are clipped (surface_clipping.h) and fanned, and
// their edges on the primitive's own clip planes are kept as the boundary segments of the
// caps (solid_caps.h).
#pragma once
#include <cmath>
#include <cstddef>
#include <vector>

#include <Eigen/Dense>

#include "modeling/tessellation/surface_clipping.h"
#include "modeling/tessellation/tessellation.h"

namespace qacc::tess {

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

  // Working polygons of addPolygon, kept across calls (one allocation per builder).
  Polygon poly_{}, scratch_{};

  Vector3d normalAt(const ClipVertex& v, const Vector3d& towards) const {
    const Vector3d& p = v.pos;
    Vector3d g = q.gradient(p);
    const double scale = 1.0 + p.norm();
    if (!(g.norm() > 1e-9 * scale)) {  // singular point (cone apex): step into the triangle
      g = q.gradient(domain.position(v.coord + 1e-4 * (towards - v.coord)));
    }
    const double n = g.norm();
    return n > 0 ? Vector3d(g / n) : Vector3d(0, 0, 1);
  }

  void emit(const ClipVertex& a, const ClipVertex& b, const ClipVertex& c) {
    const Vector3d &pa = a.pos, &pb = b.pos, &pc = c.pos;
    if (pa == pb || pb == pc || pa == pc) return;
    const Vector3d fn = (pb - pa).cross(pc - pa);
    if (!(fn.norm() > 0)) return;
    const Vector3d centre = (a.coord + b.coord + c.coord) / 3.0;
    Vector3d na = normalAt(a, centre), nb = normalAt(b, centre), nc = normalAt(c, centre);
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

  unsigned onPlanes(const Vector3d& p) const {  // grid vertices (world position p) that lie on clip planes
    unsigned t = 0;
    for (std::size_t k = 0; k < planes.size() && k < 32; ++k) {
      const double g = planes[k].eval(p);
      if (std::abs(g) <= 1e-11 * (planes[k].p.head<3>().norm() * p.norm() + std::abs(planes[k].p[3]) + 1e-300))
        t |= 1u << k;
    }
    return t;
  }

  void addTriangle(const Vector3d& a, const Vector3d& b, const Vector3d& c) {
    const Vector3d corners[3] = {a, b, c};
    addPolygon(corners, 3);
  }

  void addPolygon(const std::vector<Vector3d>& corners) { addPolygon(corners.data(), corners.size()); }

  // A domain point as a polygon vertex: its world position and the clip planes it lies on.
  ClipVertex vertex(const Vector3d& coord) const {
    const Vector3d p = domain.position(coord);
    return {coord, p, onPlanes(p)};
  }

  // A convex domain polygon, clipped as a whole then fanned.
  void addPolygon(const Vector3d* corners, std::size_t n) {
    poly_.clear();
    for (std::size_t i = 0; i < n; ++i) poly_.push_back(vertex(corners[i]));
    clipAndEmit();
  }
  // The same from vertices made by vertex() (a grid's, made once for the polygons around them).
  void addPolygon(const ClipVertex* corners, std::size_t n) {
    poly_.assign(corners, corners + n);
    clipAndEmit();
  }

  // poly_ clipped, fanned into triangles, and its edges on cap planes kept.
  void clipAndEmit() {
    Polygon& poly = poly_;
    clipPolygon(poly, scratch_, domain, planes);
    if (poly.empty()) return;
    for (std::size_t i = 1; i + 1 < poly.size(); ++i) emit(poly[0], poly[i], poly[i + 1]);
    if (cap_planes == 0) return;
    // Orientation of the polygon against the outward normal (Newell normal vs gradient).
    Vector3d newell = Vector3d::Zero(), grad = Vector3d::Zero();
    for (std::size_t i = 0; i < poly.size(); ++i) {
      newell += poly[i].pos.cross(poly[(i + 1) % poly.size()].pos);
      grad += q.gradient(poly[i].pos);
    }
    const bool outward = newell.dot(grad) >= 0;
    for (std::size_t i = 0; i < poly.size(); ++i) {
      const std::size_t j = (i + 1) % poly.size();
      const unsigned common = poly[i].tags & poly[j].tags;
      if (!common || (common & (common - 1))) continue;  // on no plane, or along a plane-plane line
      const Vector3d &Pi = poly[i].pos, &Pj = poly[j].pos;
      if (Pi == Pj) continue;
      for (std::size_t k = 0; k < cap_planes && k < 32; ++k) {
        if (common != (1u << k)) continue;
        // The cap runs the shared edge the other way round.
        if (outward) caps.per_plane[k].push_back({Pj, Pi, poly[j].tags, poly[i].tags});
        else caps.per_plane[k].push_back({Pi, Pj, poly[i].tags, poly[j].tags});
      }
    }
  }

  void addQuad(const Vector3d& a, const Vector3d& b, const Vector3d& c, const Vector3d& d) {
    addTriangle(a, b, c);
    addTriangle(a, c, d);
  }
  void addQuad(const ClipVertex& a, const ClipVertex& b, const ClipVertex& c, const ClipVertex& d) {
    const ClipVertex abc[3] = {a, b, c}, acd[3] = {a, c, d};
    addPolygon(abc, 3);
    addPolygon(acd, 3);
  }
};

}  // namespace qacc::tess
