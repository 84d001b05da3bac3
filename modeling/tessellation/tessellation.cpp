// The dispatcher of the tessellation (tessellation.h): per primitive, the method by the
// affine type of its quadric — parametric grid (parametric_grid.h), planar polygon, or
// marching tetrahedra (marching_piece.h) — over its region (clip_region.h), then the caps
// of solids (solid_caps.h) and the chord error (chord_error.cpp); per scene, objects with
// an exact surface by their own triangles (exact_facets.h).
#include "modeling/tessellation/tessellation.h"

#include <algorithm>
#include <cmath>
#include <stdexcept>
#include <utility>

#include "modeling/geometry/primitive_bounds.h"
#include "modeling/geometry/quadric_type.h"
#include "modeling/tessellation/clip_region.h"
#include "modeling/tessellation/exact_facets.h"
#include "modeling/tessellation/marching_piece.h"
#include "modeling/tessellation/parametric_grid.h"
#include "modeling/tessellation/quadric_frame.h"
#include "modeling/tessellation/screen_error.h"
#include "modeling/tessellation/solid_caps.h"
#include "modeling/tessellation/surface_builder.h"

namespace qacc {

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

namespace {

using namespace tess;

// A plane (a facet, a planar piece): the clip polygon itself, from a square around the
// region that holds it. False when the plane has no normal.
bool emitPlanarPiece(SurfaceBuilder& sb, Domain& domain, const Quadric& q, const TessellationRegion& region) {
  const Vector3d n = q.gradient(region.box.center());
  const double nn = n.norm();
  if (!(nn > 0)) return false;
  const Vector3d un = n / nn;
  const Vector3d o = region.box.center() - (q.eval(region.box.center()) / nn) * un;
  const Vector3d b1 = (std::abs(un.x()) < 0.9 ? Vector3d::UnitX() : Vector3d::UnitY()).cross(un).normalized();
  const Vector3d b2 = un.cross(b1);
  const double R = region.diag * 1.01 + 1e-9;
  domain.linear = true;
  domain.position = [o, b1, b2](const Vector3d& uv) { return Vector3d(o + uv.x() * b1 + uv.y() * b2); };
  sb.addPolygon({Vector3d(-R, -R, 0), Vector3d(R, -R, 0), Vector3d(R, R, 0), Vector3d(-R, R, 0)});
  return true;
}

// Caps on the primitive's own planes [0, capPlanes) from the segments the surface left.
void addCaps(const CapSegments& caps, std::size_t capPlanes, const std::vector<HalfSpace>& planes, const Quadric& q,
             TriangleMesh3& mesh) {
  const std::vector<Vector3d> polyVerts = capPlanes ? polytopeVertices(planes) : std::vector<Vector3d>();
  for (std::size_t k = 0; k < capPlanes; ++k) buildCap(k, caps.per_plane[k], planes, polyVerts, q, mesh);
}

PrimitiveTessellation tessellateOnce(const Primitive& prim, int target, const Camera* camera, double aspect,
                                     int chordSamples, bool forceMarching = false) {
  PrimitiveTessellation out;
  const Quadric q = prim.quadric.normalized();
  // QuadricType::All has no parametric branch: it selects marching tetrahedra over the region.
  const QuadricType type = forceMarching ? QuadricType::All
                                         : (prim.isPlanar() ? QuadricType::Plane : quadricType(prim.quadric));
  double ltol = 0;
  const Frame f = axialFrame(prim.quadric, type, &ltol);
  const TessellationRegion region = tessellationRegion(prim, q, type, f, ltol, camera, aspect);
  if (region.empty) return out;

  CapSegments caps;
  caps.per_plane.resize(prim.clip.size());
  Domain domain;
  const std::size_t capPlanes = (prim.solid && !prim.isPlanar()) ? prim.clip.size() : 0;
  SurfaceBuilder sb{q, domain, region.planes, capPlanes, out.mesh, caps};
  if (emitNaturalQuadricGrid(sb, domain, type, f, ltol, region.vertices, target)) {
    out.method = TessellationMethod::Parametric;
  } else if (type == QuadricType::Plane) {
    out.method = TessellationMethod::Planar;
    if (!emitPlanarPiece(sb, domain, q, region)) return out;
  } else {
    out.method = TessellationMethod::MarchingTetrahedra;
    domain.linear = true;
    domain.position = [](const Vector3d& p) { return p; };
    marchQuadricPiece(sb, q, region.box, region.planes, target);
  }
  out.surface_triangles = out.mesh.size();
  addCaps(caps, capPlanes, region.planes, q, out.mesh);
  out.cap_triangles = out.mesh.size() - out.surface_triangles;
  if (out.mesh.size() == 0) out.method = TessellationMethod::Empty;
  const ChordError ce = measureChordError(out.mesh, prim.quadric, 0, out.surface_triangles, chordSamples);
  out.max_chord_error = ce.max;
  out.mean_chord_error = ce.mean;
  return out;
}

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

void checkOptions(const TessellationOptions& options) {
  if (options.chord_error > 0 && options.pixel_error > 0)
    throw std::invalid_argument("tessellation: chord_error and pixel_error are exclusive (both > 0)");
  if (!(options.pixel_error >= 0) || !std::isfinite(options.pixel_error))
    throw std::invalid_argument("tessellation: pixel_error must be a finite number >= 0");
}

// pixel_error mode: refined until the measured projected chord error is at most the bound.
PrimitiveTessellation tessellateToPixels(const Primitive& prim, const TessellationOptions& options,
                                         const Camera* camera, double aspect, const ScreenView& view) {
  const PrimitiveBounds bounds = primitiveBounds(prim);
  int target = 8;
  auto measured = [&](PrimitiveTessellation t) {
    const PixelError pe = measurePixelError(t.mesh, prim.quadric, view, 0, t.surface_triangles, options.chord_samples);
    t.max_pixel_error = pe.max;
    t.mean_pixel_error = pe.mean;
    return t;
  };
  PrimitiveTessellation t = measured(tessellateCovering(prim, target, camera, aspect, options.chord_samples));
  if (bounds.empty || (bounds.bounded && !view.boxOnScreen(bounds.box, 2.0))) return t;  // off screen: coarsest
  while (t.max_pixel_error > options.pixel_error && t.method != TessellationMethod::Planar &&
         t.method != TessellationMethod::Empty && target * 2 <= options.max_triangles) {
    target *= 2;
    t = measured(tessellateCovering(prim, target, camera, aspect, options.chord_samples));
  }
  return t;
}

}  // namespace

PrimitiveTessellation tessellatePrimitive(const Primitive& prim, const TessellationOptions& options,
                                          const Camera* camera, double aspect, const ScreenView* view) {
  checkOptions(options);
  if (options.pixel_error > 0) {
    if (!view) throw std::invalid_argument("tessellation: pixel_error needs the scene's view");
    return tessellateToPixels(prim, options, camera, aspect, *view);
  }
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

TriangleMesh3 tessellateScene(const Scene& scene, const TessellationOptions& options, TessellationReport* report) {
  checkOptions(options);
  TriangleMesh3 all;
  TessellationReport rep;
  const double aspect = double(scene.width) / double(scene.height);
  const ScreenView view(scene.camera, scene.width, scene.height);
  double meanSum = 0, pixelMeanSum = 0;
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
      const ExactSurface& surface = *scene.exact_surfaces[std::size_t(e)];
      ExactSurfaceMesh em = tess::tessellateExact(surface, object->count, options, &view);
      if (options.pixel_error > 0) {
        const double px = em.max_error * view.maxPixelsPerUnit(surface.bounds());
        rep.max_pixel_error = std::max(rep.max_pixel_error, px);
        pixelMeanSum += em.mean_error * view.maxPixelsPerUnit(surface.bounds());
      }
      const TriangleMesh3 t = tess::exactSurfaceFacets(std::move(em), p.object, p.material, int(i));
      const std::size_t n = t.size();
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
    PrimitiveTessellation t = tessellatePrimitive(p, options, &scene.camera, aspect, &view);
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
    rep.max_pixel_error = std::max(rep.max_pixel_error, t.max_pixel_error);
    pixelMeanSum += t.mean_pixel_error;
    ++measured;
  }
  rep.mean_chord_error = measured ? meanSum / double(measured) : 0.0;
  rep.mean_pixel_error = measured ? pixelMeanSum / double(measured) : 0.0;
  if (report) *report = rep;
  return all;
}

}  // namespace qacc
