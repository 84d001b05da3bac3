// The dispatcher of the tessellation (tessellation.h): per primitive, the method by the
// affine type of its quadric — parametric grid (parametric_grid.h), planar polygon, or
// marching tetrahedra (marching_piece.h) — over its region (clip_region.h), then the caps
// of solids (solid_caps.h) and the chord error (chord_error.cpp); per scene, objects with
// an exact surface by their own triangles (exact_facets.h).
#include "modeling/tessellation/tessellation.h"

#include <algorithm>
#include <atomic>
#include <cmath>
#include <optional>
#include <stdexcept>
#include <utility>

#include "modeling/geometry/primitive_bounds.h"
#include "modeling/geometry/quadric_type.h"
#include "modeling/support/limits.h"
#include "modeling/support/parallel_errors.h"
#include "modeling/tessellation/clip_region.h"
#include "modeling/tessellation/exact_facets.h"
#include "modeling/tessellation/grid_density.h"
#include "modeling/tessellation/marching_piece.h"
#include "modeling/tessellation/parametric_grid.h"
#include "modeling/tessellation/piece_boundary.h"
#include "modeling/tessellation/piece_in_view.h"
#include "modeling/tessellation/quadric_frame.h"
#include "modeling/tessellation/screen_error.h"
#include "modeling/tessellation/shared_boundaries.h"
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

// Caps on the region's planes [0, capPlanes) from the segments the surface left.
void addCaps(const CapSegments& caps, std::size_t capPlanes, const std::vector<HalfSpace>& planes, const Quadric& q,
             TriangleMesh3& mesh) {
  const std::vector<Vector3d> polyVerts = capPlanes ? polytopeVertices(planes) : std::vector<Vector3d>();
  for (std::size_t k = 0; k < capPlanes; ++k) buildCap(k, caps.per_plane[k], planes, polyVerts, q, mesh);
}

// How fine: a triangle budget, or (view set) a projected chord error in pixels, the grid
// counts and marching cells from the curvature (grid_density.h, marching_piece.h) times
// `scale` (the refinement when a measurement finds the bound missed).
struct Level {
  int target = 128;
  const ScreenView* view = nullptr;
  double epsilon = 0;
  double scale = 1;
  int max_triangles = 1 << 20;
  const PrimitiveBounds* bounds = nullptr;  // the piece's exact extent (pixel error: coverage check)
};

// Grid counts for the level, the total kept within max_triangles.
GridChooser gridChooser(const Level& lv, QuadricType type, const Domain& domain, const Quadric& q,
                        const std::vector<HalfSpace>& planes) {
  if (!lv.view) return gridByTarget(type, lv.target);
  return [&lv, &domain, &q, &planes](double v0, double v1) {
    const ProjectedCurvature c = projectedCurvature(domain, q, v0, v1, planes, *lv.view);
    Grid g = gridForPixelError(c, v0, v1, lv.epsilon, lv.scale);
    const double n = 2.0 * g.nu * g.nv;
    if (n > lv.max_triangles) {
      const double shrink = std::sqrt(lv.max_triangles / n);
      g.nu = std::max(3, int(g.nu * shrink));
      g.nv = std::max(1, int(g.nv * shrink));
    }
    return g;
  };
}

PrimitiveTessellation tessellateOnce(const Primitive& prim, const Level& lv, const Camera* camera, double aspect,
                                     bool forceMarching = false) {
  PrimitiveTessellation out;
  const Quadric q = prim.quadric.normalized();
  // QuadricType::All has no parametric branch: it selects marching tetrahedra over the region.
  const QuadricType type = forceMarching ? QuadricType::All
                                         : (prim.isPlanar() ? QuadricType::Plane : quadricType(prim.quadric));
  double ltol = 0;
  const Frame f = axialFrame(prim.quadric, type, &ltol);
  const TessellationRegion region = tessellationRegion(prim, q, type, f, ltol, camera, aspect);
  if (region.empty) return out;

  // A solid is closed: caps on every plane that bounds its region — its own clip planes,
  // and the view frustum's when the frustum bounds it (region.planes) — for a planar solid
  // (a slab, a half-space) as for a curved one. OpenCSG's parity counts need closed leaves.
  const std::size_t capPlanes = prim.solid ? region.planes.size() : 0;
  CapSegments caps;
  caps.per_plane.resize(capPlanes);
  Domain domain;
  SurfaceBuilder sb{q, domain, region.planes, capPlanes, out.mesh, caps};
  if (emitNaturalQuadricGrid(sb, domain, type, f, ltol, region.vertices, gridChooser(lv, type, domain, q, region.planes))) {
    out.method = TessellationMethod::Parametric;
  } else if (type == QuadricType::Plane) {
    out.method = TessellationMethod::Planar;
    if (!emitPlanarPiece(sb, domain, q, region)) return out;
  } else {
    out.method = TessellationMethod::MarchingTetrahedra;
    domain.linear = true;
    domain.position = [](const Vector3d& p) { return p; };
    domain.surface = &q;
    if (lv.view) {
      Eigen::AlignedBox3d box = surfaceBox(q, region.box, region.planes);
      int n = marchingCellsForPixelError(q, box, region.planes, *lv.view, lv.epsilon, lv.scale, lv.max_triangles);
      // A piece smaller than a cell (a sliver of a B-spline cell: bspline_volume_g1 has some
      // 1e-4 across, in slabs so thin that the scan keeps a box 0.1 across) is marched in
      // its exact extent, one cell across: in cells larger than itself, the clip planes would
      // cut the cells' triangles into a facet off the surface, pixels away from the piece.
      if (lv.bounds && lv.bounds->bounded && !lv.bounds->empty &&
          8 * lv.bounds->box.sizes().maxCoeff() < box.sizes().maxCoeff() / n) {
        box = lv.bounds->box;
        n = 1;
      }
      marchQuadricBox(sb, q, box, n);
    } else {
      // At a budget the cells count along the region's box, or along the piece's exact
      // extent (padded) when the level carries it (tessellateCovering's retry).
      Eigen::AlignedBox3d box = region.box;
      if (lv.bounds && lv.bounds->bounded && !lv.bounds->empty) {
        Eigen::AlignedBox3d padded = lv.bounds->box;
        const double pad = 0.05 * padded.sizes().maxCoeff();
        padded.min().array() -= pad;
        padded.max().array() += pad;
        const Eigen::AlignedBox3d both = box.intersection(padded);
        if (!both.isEmpty()) box = both;
      }
      marchQuadricPiece(sb, q, box, region.planes, lv.target);
    }
  }
  out.surface_triangles = out.mesh.size();
  if (!prim.clip.empty()) out.boundary_defects = checkPieceBoundary(out.mesh, out.surface_triangles, region.planes).defects();
  addCaps(caps, capPlanes, region.planes, q, out.mesh);
  out.cap_triangles = out.mesh.size() - out.surface_triangles;
  if (out.mesh.size() == 0) out.method = TessellationMethod::Empty;
  return out;
}

// The chord error (and with a view the pixel error) of the tessellation that is kept: the
// choices between tries (tessellateReaching, tessellateCovering) read their triangles, reach
// and boundary defects only, so the errors are measured once, on the one returned (and again
// after stitching, on a piece whose strips were rebuilt). `view`: the pixel error too.
void measureErrors(PrimitiveTessellation& t, const Primitive& prim, const ScreenView* view, int chordSamples) {
  const ChordError ce = measureChordError(t.mesh, prim.quadric, 0, t.surface_triangles, chordSamples);
  t.max_chord_error = ce.max;
  t.mean_chord_error = ce.mean;
  if (view) {
    const PixelError pe = measurePixelError(t.mesh, prim.quadric, *view, 0, t.surface_triangles, chordSamples);
    t.max_pixel_error = pe.max;
    t.mean_pixel_error = pe.mean;
  }
}

// Whether the mesh reaches the piece's exact extent in every direction (within `tol`).
bool reachesBounds(const TriangleMesh3& mesh, const Eigen::AlignedBox3d& bounds, double tol) {
  Eigen::AlignedBox3d box;
  for (const auto& p : mesh.positions) box.extend(p);
  if (box.isEmpty()) return false;
  return ((box.min() - bounds.min()).array() <= tol).all() && ((bounds.max() - box.max()).array() <= tol).all();
}

// A parametric grid spans the whole natural surface; a small clipped piece of a large
// surface (a Bernstein-Bézier cell far out on a hyperboloid sheet) can receive few or none
// of its triangles. With a triangle budget: when a clipped piece gets under a quarter of its
// target, marching tetrahedra over the piece's own region is tried and the denser mesh
// kept. To a pixel error: when the mesh of a bounded clipped piece falls short of the
// piece's exact extent (primitive_bounds.h) by more than 2ε pixels, the grid is refined
// (x2, up to three times), then marching tetrahedra is tried and kept if it reaches further.
PrimitiveTessellation tessellateReaching(const Primitive& prim, const Level& lv, const Camera* camera, double aspect) {
  PrimitiveTessellation t = tessellateOnce(prim, lv, camera, aspect);
  const bool parametric = t.method == TessellationMethod::Parametric || t.method == TessellationMethod::Empty;
  if (prim.clip.empty() || prim.isPlanar() || !parametric) return t;
  if (!lv.view) {
    if (4 * t.surface_triangles < std::size_t(lv.target)) {
      PrimitiveTessellation m = tessellateOnce(prim, lv, camera, aspect, true);
      if (m.surface_triangles > t.surface_triangles) return m;
    }
    return t;
  }
  if (!lv.bounds || !lv.bounds->bounded || lv.bounds->empty) return t;
  const Eigen::AlignedBox3d& box = lv.bounds->box;
  const double tol = 2 * lv.epsilon / lv.view->maxPixelsPerUnit(box) + 1e-9 * box.sizes().norm();
  Level finer = lv;
  for (int round = 0; round < 3 && !reachesBounds(t.mesh, box, tol); ++round) {
    finer.scale *= 2;
    if (2.0 * t.mesh.size() > lv.max_triangles) break;
    t = tessellateOnce(prim, finer, camera, aspect);
  }
  if (!reachesBounds(t.mesh, box, tol)) {
    PrimitiveTessellation m = tessellateOnce(prim, lv, camera, aspect, true);
    if (reachesBounds(m.mesh, box, tol) || m.surface_triangles > t.surface_triangles) return m;
  }
  return t;
}

// A clipped parametric piece whose triangles are not a proper piece of the surface
// (piece_boundary.h: vertices outside a plane, open edges off the planes) gets a finer grid
// (x2, twice), then marching tetrahedra over its region; the first proper mesh is kept, or
// else the one with the fewest defects.
PrimitiveTessellation coveringTry(const Primitive& prim, const Level& lv, const Camera* camera, double aspect) {
  PrimitiveTessellation t = tessellateReaching(prim, lv, camera, aspect);
  if (t.boundary_defects == 0 || t.method != TessellationMethod::Parametric) return t;
  Level finer = lv;
  for (int round = 0; round < 2; ++round) {
    finer.scale *= 2;
    finer.target *= 4;
    if (finer.target > lv.max_triangles || 2.0 * t.mesh.size() > lv.max_triangles) break;
    PrimitiveTessellation f = tessellateReaching(prim, finer, camera, aspect);
    if (f.boundary_defects < t.boundary_defects) t = std::move(f);
    if (t.boundary_defects == 0) return t;
  }
  PrimitiveTessellation m = tessellateOnce(prim, lv, camera, aspect, true);
  if (m.boundary_defects < t.boundary_defects && m.method != TessellationMethod::Empty) return m;
  return t;
}

// coveringTry, its errors measured.
PrimitiveTessellation tessellateCovering(const Primitive& prim, const Level& lv, const Camera* camera, double aspect,
                                         int chordSamples) {
  PrimitiveTessellation t = coveringTry(prim, lv, camera, aspect);
  measureErrors(t, prim, lv.view, chordSamples);
  return t;
}

// How far the mesh strays outside `box`, in units of the box's largest side.
double strayOutside(const TriangleMesh3& mesh, std::size_t surface, const Eigen::AlignedBox3d& box) {
  double worst = 0;
  for (std::size_t t = 0; t < std::min(surface, mesh.triangles.size()); ++t)
    for (int k = 0; k < 3; ++k) {
      const Vector3d& x = mesh.positions[std::size_t(mesh.triangles[t][std::size_t(k)])];
      worst = std::max(worst, (box.min() - x).cwiseMax(x - box.max()).maxCoeff());
    }
  return worst / std::max(box.sizes().maxCoeff(), 1e-300);
}

// At a triangle budget or a chord error the piece's extent is not computed up front; a
// marched piece is checked against it afterwards. Marching cells that count along the region's
// box can be far larger than the piece across a thin slab of a cell (bspline_volume_g1 has
// slabs 1e-4 thick that the surface crosses at a grazing angle): the cells' triangles, cut by
// the slab's planes, then lie off the piece (up to 0.75 world units on that scene). Such a
// piece is marched again in its exact extent, then with the cells halved up to three times,
// until its surface vertices lie within a tenth of its size of that extent; the one that
// strays least (with no more boundary defects) is kept. A marched piece, or one left with
// boundary defects, whose extent is empty draws nothing, as at a pixel error
// (bspline_volume_g1 had marched pieces with no point inside their region, their facets 0.05
// world units off any surface). `extent` keeps the piece's extent across calls for the same
// piece (the chord-error loop), computed the first time it is needed.
PrimitiveTessellation tessellateCovering(const Primitive& prim, int target, const Camera* camera, double aspect,
                                         int chordSamples, std::optional<PrimitiveBounds>& extent) {
  Level lv;
  lv.target = target;
  PrimitiveTessellation t = tessellateCovering(prim, lv, camera, aspect, chordSamples);
  const bool marched = t.method == TessellationMethod::MarchingTetrahedra;
  if (prim.clip.empty() || (!marched && t.boundary_defects == 0)) return t;
  if (!extent) extent = primitiveBounds(prim);
  const PrimitiveBounds& bounds = *extent;
  if (bounds.empty) return PrimitiveTessellation{};
  if (!marched || !bounds.bounded) return t;
  constexpr double kStray = 0.1;
  double stray = strayOutside(t.mesh, t.surface_triangles, bounds.box);
  Level exact = lv;
  exact.bounds = &bounds;
  for (int round = 0; round < 4 && stray > kStray; ++round) {
    PrimitiveTessellation m = tessellateOnce(prim, exact, camera, aspect, true);
    exact.target *= 4;  // cells halved
    if (m.surface_triangles == 0) continue;
    const double s = strayOutside(m.mesh, m.surface_triangles, bounds.box);
    if (s < stray && m.boundary_defects <= t.boundary_defects) {
      measureErrors(m, prim, nullptr, chordSamples);
      t = std::move(m);
      stray = s;
    }
  }
  return t;
}

void checkOptions(const TessellationOptions& options) {
  if (options.chord_error > 0 && options.pixel_error > 0)
    throw std::invalid_argument("tessellation: chord_error and pixel_error are exclusive (both > 0)");
  if (!(options.pixel_error >= 0) || !std::isfinite(options.pixel_error))
    throw std::invalid_argument("tessellation: pixel_error must be a finite number >= 0");
}

// pixel_error mode: grid counts and marching cells from the projected curvature. When the
// measured error is under ε/2 the counts are scaled down once by √(measured / 0.8ε) and the
// coarser mesh kept if it measures within ε; when the
// measured error still exceeds the bound (terms the second-order estimate neglects), the
// counts are scaled by the square root of the excess, at most three times. Pieces entirely
// off screen get the coarsest mesh.
PrimitiveTessellation tessellateToPixels(const Primitive& prim, const TessellationOptions& options,
                                         const Camera* camera, double aspect, const ScreenView& view) {
  const PrimitiveBounds bounds = primitiveBounds(prim);
  // No point of the surface inside the clip region: nothing to draw, as the accelerator draws
  // nothing (its screen box, raster/pixel/window_primitive.h, is the same extent's). A grid
  // would still leave triangles whose vertices lie outside the region.
  if (bounds.empty) return PrimitiveTessellation{};
  if (bounds.bounded && !view.boxOnScreen(bounds.box, 2.0)) {
    Level coarse;
    coarse.target = 8;
    PrimitiveTessellation t = tessellateOnce(prim, coarse, camera, aspect);
    measureErrors(t, prim, coarse.view, options.chord_samples);
    return t;
  }
  Level lv;
  lv.view = &view;
  lv.epsilon = options.pixel_error;
  lv.max_triangles = options.max_triangles;
  lv.bounds = &bounds;
  const int samples = std::max(3, options.chord_samples);  // the centre of each triangle too
  PrimitiveTessellation t = tessellateCovering(prim, lv, camera, aspect, samples);
  const bool refinable = t.method != TessellationMethod::Planar && t.method != TessellationMethod::Empty;
  if (!refinable || t.max_pixel_error <= 0) return t;
  const double eps = options.pixel_error;
  if (t.max_pixel_error < 0.5 * eps) {
    // The curvature bound is loose here (the largest curvature and scale over the piece set
    // the whole grid): one coarser try, kept when its measured error stays within ε.
    Level coarser = lv;
    coarser.scale *= std::sqrt(t.max_pixel_error / (0.8 * eps));
    PrimitiveTessellation c = tessellateCovering(prim, coarser, camera, aspect, samples);
    if (c.max_pixel_error <= eps && c.mesh.size() < t.mesh.size()) return c;
    return t;
  }
  for (int round = 0; round < 3 && t.max_pixel_error > eps && t.mesh.size() < std::size_t(options.max_triangles);
       ++round) {
    lv.scale *= std::min(4.0, 1.1 * std::sqrt(t.max_pixel_error / eps));
    t = tessellateCovering(prim, lv, camera, aspect, samples);
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
  std::optional<PrimitiveBounds> extent;  // computed once, when a try needs it
  if (options.chord_error <= 0)
    return tessellateCovering(prim, std::max(2, options.triangles), camera, aspect, options.chord_samples, extent);
  int target = 8;
  PrimitiveTessellation t = tessellateCovering(prim, target, camera, aspect, options.chord_samples, extent);
  while (t.max_chord_error > options.chord_error && t.method != TessellationMethod::Planar &&
         t.method != TessellationMethod::Empty && target * 2 <= options.max_triangles) {
    target *= 2;
    t = tessellateCovering(prim, target, camera, aspect, options.chord_samples, extent);
  }
  return t;
}

TriangleMesh3 tessellateScene(const Scene& scene, const TessellationOptions& options, TessellationReport* report) {
  checkOptions(options);
  TessellationReport rep;
  const double aspect = double(scene.width) / double(scene.height);
  const ScreenView view(scene.camera, scene.width, scene.height);
  const std::size_t n = scene.primitives.size();
  // Which primitives are drawn by their object's exact surface (at the object's first piece).
  std::vector<int> exactOf(n, -1);
  std::vector<bool> exactFirst(n, false);
  {
    std::vector<bool> exactDone(scene.exact_surfaces.size(), false);
    for (std::size_t i = 0; i < n; ++i) {
      const int o = scene.primitives[i].object;
      const SceneObject* object = o >= 0 && std::size_t(o) < scene.objects.size() ? &scene.objects[std::size_t(o)] : nullptr;
      const int e = object ? object->exact_surface : -1;
      if (e < 0 || std::size_t(e) >= scene.exact_surfaces.size()) continue;
      exactOf[i] = e;
      exactFirst[i] = !exactDone[std::size_t(e)];
      exactDone[std::size_t(e)] = true;
    }
  }
  // The triangles made so far, against options.max_scene_triangles.
  std::atomic<std::size_t> made{0};
  auto count = [&](std::size_t k) {
    if (made.fetch_add(k, std::memory_order_relaxed) + k > options.max_scene_triangles)
      throw std::length_error(Limits::exceeded("facets: the tessellation of " + std::to_string(n) +
                                                   " primitives (counted while tessellating, stopped at the limit)",
                                               options.max_scene_triangles + 1, "triangles or more",
                                               options.max_scene_triangles, "max-triangles"));
  };
  // Pieces, in parallel (each depends on its primitive and the view only).
  // Whether each surely reaches the view (piece_in_view.h): only those are stitched below.
  std::vector<PrimitiveTessellation> pieces(n);
  std::vector<char> inView(n, 0);
  const tess::PieceInView inViewTest(view);
  ParallelErrors errors;
#pragma omp parallel for schedule(dynamic, 1)
  for (long i = 0; i < long(n); ++i)
    errors.run([&] {
      const std::size_t k = std::size_t(i);
      if (exactOf[k] < 0) {
        pieces[k] = tessellatePrimitive(scene.primitives[k], options, &scene.camera, aspect, &view);
        count(pieces[k].mesh.size());
        inView[k] = inViewTest.surelyInView(scene.primitives[k], pieces[k].mesh, pieces[k].surface_triangles);
      }
    });
  errors.rethrow();
  // Shared boundaries sampled once for both sides (shared_boundaries.h).
  std::vector<TriangleMesh3*> meshes(n, nullptr);
  std::vector<std::size_t> surface(n, 0);
  // Only pieces that surely reach the view are stitched: those are present whether or not
  // view culling removed the pieces outside it, so the triangles of a kept piece never depend
  // on the neighbours culling removed (a piece culling removes has no point in the view, so
  // its shared boundary with a kept piece lies outside the view as well).
  for (std::size_t i = 0; i < n; ++i) {
    surface[i] = pieces[i].surface_triangles;
    if (inView[i]) meshes[i] = &pieces[i].mesh;
  }
  tess::SharedBoundarySampling sampling;
  sampling.samples = options.chord_samples;
  if (options.pixel_error > 0) {
    sampling.view = &view;
    sampling.pixels = options.pixel_error;
  } else {
    sampling.chordError.resize(n);
    for (std::size_t i = 0; i < n; ++i) sampling.chordError[i] = pieces[i].max_chord_error;
  }
  const tess::StitchReport stitched = tess::stitchSharedBoundaries(scene.primitives, meshes, surface, sampling);
  rep.shared_planes = stitched.shared_planes;
  rep.stitched_pieces = stitched.zipped;
  rep.unstitched_planes = stitched.refused_planes;
  rep.unstitched_pieces = stitched.refused_pieces;
  // Stitching moved triangles between surface and caps: every piece's counts from here on
  // are the stitched ones, and a rebuilt piece's errors are measured again, on the triangles
  // it is drawn with.
#pragma omp parallel for schedule(dynamic, 16)
  for (long li = 0; li < long(n); ++li) {
    const std::size_t i = std::size_t(li);
    PrimitiveTessellation& t = pieces[i];
    t.surface_triangles = surface[i];
    t.cap_triangles = t.mesh.size() - surface[i];
    if (i < stitched.rebuilt.size() && stitched.rebuilt[i])
      measureErrors(t, scene.primitives[i], options.pixel_error > 0 ? &view : nullptr, options.chord_samples);
  }

  // The report in scene order (its means are sums in that order), the exact surfaces' meshes
  // made in that order too; the meshes are listed in drawing order (slots), then each is
  // copied into its own slice of the scene's arrays, in parallel, and released.
  double meanSum = 0, pixelMeanSum = 0;
  std::size_t measured = 0;
  struct Slot {
    TriangleMesh3* mesh;
    int primitive;  // its piece (object, material and primitive of every triangle), or -1: the
                    // mesh carries its own per-triangle tags (exact surfaces)
  };
  std::vector<Slot> slots;
  slots.reserve(n);
  std::vector<TriangleMesh3> pieceless;  // exact surfaces of objects without a piece
  pieceless.reserve(scene.objects.size());
  // The true surface of object `o`, tagged with primitive `prim` (its first piece, or -1 when
  // it has none).
  auto drawExact = [&](std::size_t o, int prim, int material) {
    const SceneObject& object = scene.objects[o];
    const ExactSurface& surf = *scene.exact_surfaces[std::size_t(object.exact_surface)];
    // Sized by the object's whole model when the modeler gave it, so that view culling
    // (which lowers the pieces emitted) does not change the mesh.
    ExactSurfaceMesh em =
        tess::tessellateExact(surf, object.model_cells > 0 ? object.model_cells : object.count, options, &view);
    if (options.pixel_error > 0) {
      const double s = view.maxPixelsPerUnit(surf.bounds());
      rep.max_pixel_error = std::max(rep.max_pixel_error, em.max_error * s);
      pixelMeanSum += em.mean_error * s;
    }
    const int grid = em.grid;
    const double maxError = em.max_error, meanError = em.mean_error;
    TriangleMesh3 t = tess::exactSurfaceFacets(std::move(em), int(o), material, prim);
    count(t.size());
    ++rep.exact_surfaces;
    rep.exact_triangles += t.size();
    rep.triangles += t.size();
    rep.exact_grid = std::max(rep.exact_grid, grid);
    rep.max_chord_error = std::max(rep.max_chord_error, maxError);
    meanSum += meanError;
    ++measured;
    return t;
  };
  // An object with an exact surface and no piece (view culling removed them all) is still
  // drawn, in object order, as the reference draws it: its mesh is the whole surface's and
  // its chords can reach the view where no piece of the surface does.
  auto hasNoPiece = [&](std::size_t o) {
    const SceneObject& object = scene.objects[o];
    return object.count == 0 && object.exact_surface >= 0 &&
           std::size_t(object.exact_surface) < scene.exact_surfaces.size();
  };
  std::size_t nextObject = 0;  // the objects before it are drawn, or have pieces
  auto drawPiecelessBefore = [&](std::size_t end) {
    for (; nextObject < std::min(end, scene.objects.size()); ++nextObject)
      if (hasNoPiece(nextObject)) {
        pieceless.push_back(drawExact(nextObject, -1, scene.objects[nextObject].material));
        slots.push_back({&pieceless.back(), -1});
      }
  };
  for (std::size_t i = 0; i < n; ++i) {
    const Primitive& p = scene.primitives[i];
    if (p.object >= 0) drawPiecelessBefore(std::size_t(p.object));
    if (exactOf[i] >= 0) {
      // The object's true surface replaces its pieces, drawn once at its first piece.
      if (!exactFirst[i]) continue;
      pieces[i].mesh = drawExact(std::size_t(p.object), int(i), p.material);
      slots.push_back({&pieces[i].mesh, -1});
      continue;
    }
    PrimitiveTessellation& t = pieces[i];
    const std::size_t count = t.mesh.size();
    ++rep.primitives;
    rep.triangles += count;
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
    slots.push_back({&t.mesh, int(i)});
  }
  drawPiecelessBefore(scene.objects.size());
  // Where each slot's mesh goes: what TriangleMesh3::append in drawing order would give.
  const std::size_t m = slots.size();
  std::vector<std::size_t> vertexAt(m + 1, 0), normalAt(m + 1, 0), triangleAt(m + 1, 0);
  for (std::size_t k = 0; k < m; ++k) {
    const TriangleMesh3& mesh = *slots[k].mesh;
    vertexAt[k + 1] = vertexAt[k] + mesh.positions.size();
    normalAt[k + 1] = normalAt[k] + mesh.normals.size();
    triangleAt[k + 1] = triangleAt[k] + mesh.triangles.size();
  }
  TriangleMesh3 all;
  all.positions.resize(vertexAt[m]);
  all.normals.resize(normalAt[m]);
  all.triangles.resize(triangleAt[m]);
  all.object.resize(triangleAt[m]);
  all.material.resize(triangleAt[m]);
  all.primitive.resize(triangleAt[m]);
#pragma omp parallel for schedule(dynamic, 64)
  for (long lk = 0; lk < long(m); ++lk) {
    const std::size_t k = std::size_t(lk);
    TriangleMesh3& mesh = *slots[k].mesh;
    std::copy(mesh.positions.begin(), mesh.positions.end(), all.positions.begin() + std::ptrdiff_t(vertexAt[k]));
    std::copy(mesh.normals.begin(), mesh.normals.end(), all.normals.begin() + std::ptrdiff_t(normalAt[k]));
    const int base = int(vertexAt[k]);
    const std::size_t t0 = triangleAt[k];
    for (std::size_t t = 0; t < mesh.triangles.size(); ++t) {
      const auto& tri = mesh.triangles[t];
      all.triangles[t0 + t] = {tri[0] + base, tri[1] + base, tri[2] + base};
    }
    const int prim = slots[k].primitive;
    const Primitive* p = prim >= 0 ? &scene.primitives[std::size_t(prim)] : nullptr;
    for (std::size_t t = 0; t < mesh.triangles.size(); ++t) {
      all.object[t0 + t] = p ? p->object : mesh.object[t];
      all.material[t0 + t] = p ? p->material : mesh.material[t];
      all.primitive[t0 + t] = p ? prim : mesh.primitive[t];
    }
    mesh = TriangleMesh3();  // copied: release it
  }
  rep.mean_chord_error = measured ? meanSum / double(measured) : 0.0;
  rep.mean_pixel_error = measured ? pixelMeanSum / double(measured) : 0.0;
  if (report) *report = rep;
  return all;
}

}  // namespace qacc
