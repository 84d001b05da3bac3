// Tessellation of primitives into triangles (design §3.3), for the facet renderers.
//
// Per primitive, by the affine type of its quadric (quadric_type.h) and the eigenvectors
// of its quadratic part (the canonical frame):
//  - natural quadrics with a (u, v) parametrisation — ellipsoid (sphere), elliptic
//    cylinder, elliptic cone, elliptic paraboloid, hyperboloids of one and two sheets —
//    get a parametric grid (u around the axis, v along it or polar angle), restricted to
//    the clip polyhedron by clipping every grid triangle in parameter space: a cut point
//    is found by bisection along the parameter-space edge, so it lies on the surface and
//    on the clip plane, and the two triangles sharing an edge get the same point;
//  - planes (facets, planar pieces) become the clip polygon itself;
//  - every other piece (hyperbolic paraboloid, parabolic / hyperbolic cylinders, the
//    degenerate types) is polygonised by marching tetrahedra (Kuhn split of a cubic grid,
//    edge points refined onto the surface by Newton steps along the gradient) over the
//    bounds of its clip polyhedron, then clipped by it;
//  - solids (planar ones too) get caps: on each plane of the region (the clip planes, and
//    the frustum's when it bounds the piece), the polygon bounded by the surface's cut edges
//    on that plane (closed along the lines where two planes meet), or the whole face when the
//    surface does not cross it and it lies inside the solid. The cut edges are shared
//    exactly, so a solid's mesh is closed (csg leaves need it: docs/CSG.md).
// Unbounded pieces are limited to the view frustum (nothing outside it can be seen).
// Normals are analytic: the quadric's gradient at each vertex (outward, towards f > 0);
// caps use their plane normal.
//
// Level: `triangles` is the target number of surface triangles per primitive (caps come
// on top); `chord_error` > 0 instead refines each grid until the measured chord error
// (world units) is at most that bound.
//
// Objects with an exact surface (exact_surface.h: algebraic surfaces, which the reference
// ray-casts) are tessellated from that surface, not from their quadric pieces: the
// surface's own triangles (marching tetrahedra of the true surface), about `triangles`
// per quadric piece of the object so that a level means the same budget as for the pieces,
// or with `chord_error` the budget quadrupled from 64 per piece until the sampled distance
// to the true surface is at most the bound (up to the finest marching grid).
// An object with an exact surface and no piece (view culling removed them all) is drawn too,
// in object order, its triangles tagged with primitive -1 (the renderer's id pass takes the
// object from TriangleMesh3::object).
#pragma once
#include <array>
#include <cstddef>
#include <cstdint>
#include <vector>

#include <Eigen/Dense>

#include "modeling/scene/camera.h"
#include "modeling/geometry/primitive.h"
#include "modeling/scene/scene.h"

namespace qacc {

struct TriangleMesh3 {
  std::vector<Eigen::Vector3d> positions;
  std::vector<Eigen::Vector3d> normals;  // unit, per vertex
  std::vector<std::array<int, 3>> triangles;
  std::vector<int> object;    // per triangle: scene object index
  std::vector<int> material;  // per triangle: material index
  std::vector<int> primitive; // per triangle: primitive index in the scene, -1 for an object without pieces

  std::size_t size() const { return triangles.size(); }
  void append(const TriangleMesh3& other);
};

struct TessellationOptions {
  int triangles = 128;      // target surface triangles per primitive (>= 2)
  double chord_error = 0;   // > 0: refine until the chord error is at most this (world units)
  // > 0: every primitive tessellated so that its projected chord error is at most this many
  // pixels in the scene's view (camera, scene.width x scene.height); `triangles` is ignored.
  // Exclusive with chord_error.
  double pixel_error = 0;
  int max_triangles = 1 << 20;  // cap per primitive when refining by chord error
  int chord_samples = 6;    // barycentric subdivisions per triangle edge when measuring chord error
  // tessellateScene counts the triangles as each piece (or exact surface) is made and stops
  // (std::length_error, naming --max-triangles) the moment the count passes this.
  std::size_t max_scene_triangles = SIZE_MAX;
};

enum class TessellationMethod { Parametric, Planar, MarchingTetrahedra, Empty };
const char* tessellationMethodName(TessellationMethod m);

struct PrimitiveTessellation {
  TriangleMesh3 mesh;
  TessellationMethod method = TessellationMethod::Empty;
  std::size_t surface_triangles = 0;
  std::size_t cap_triangles = 0;
  double max_chord_error = 0;   // world units, measured (see measureChordError)
  double mean_chord_error = 0;
  double max_pixel_error = 0;   // pixels, measured in the view (pixel_error mode; screen_error.h)
  double mean_pixel_error = 0;
  // Clipped pieces: vertices outside the region and open edges off its planes
  // (piece_boundary.h); 0 for a proper piece.
  std::size_t boundary_defects = 0;
};

struct TessellationReport {
  std::size_t primitives = 0;
  std::size_t triangles = 0;
  std::size_t cap_triangles = 0;
  std::size_t parametric = 0, planar = 0, marching = 0, empty = 0;
  // Objects drawn by their exact surface's triangles (their pieces are not counted above).
  std::size_t exact_surfaces = 0, exact_triangles = 0;
  int exact_grid = 0;           // finest marching-tetrahedra grid used for them (cubes per axis)
  double max_chord_error = 0;   // over all primitives and exact surfaces, world units
  double mean_chord_error = 0;  // mean over primitives and exact surfaces of their mean
  // pixel_error mode: the achieved projected chord error in pixels, measured (not the bound),
  // over all primitives and exact surfaces (max, and mean over them of their mean).
  double max_pixel_error = 0, mean_pixel_error = 0;
  // Shared boundaries (shared_boundaries.h), over the pieces stitched (those surely in view):
  // clip planes with pieces on both sides, pieces rebuilt onto their shared polylines, and
  // what was left as tessellated, where the facets may crack: planes whose curve could not be
  // sampled, pieces whose strip could not be closed.
  std::size_t shared_planes = 0, stitched_pieces = 0, unstitched_planes = 0, unstitched_pieces = 0;
};

class ScreenView;

// `frustum` bounds unbounded pieces (pass the scene camera); may be null for bounded ones.
// `view` is required when options.pixel_error > 0 (the scene's camera and image size).
PrimitiveTessellation tessellatePrimitive(const Primitive& prim, const TessellationOptions& options,
                                          const Camera* camera = nullptr, double aspect = 4.0 / 3.0,
                                          const ScreenView* view = nullptr);
// Whole scene: per-triangle object/material/primitive indices filled in. Options are
// checked first (std::invalid_argument naming them: chord_error and pixel_error both > 0).
// Over options.max_scene_triangles: std::length_error, as soon as the count passes it.
TriangleMesh3 tessellateScene(const Scene& scene, const TessellationOptions& options,
                              TessellationReport* report = nullptr);

// Chord error of a mesh against a quadric: distance from sample points on every triangle
// (vertices, edge midpoints and a barycentric grid) to the surface, by Newton projection
// along the gradient. Triangles whose vertices are not all on the surface (caps) are skipped.
struct ChordError {
  double max = 0, mean = 0;
};
ChordError measureChordError(const TriangleMesh3& mesh, const Quadric& quadric, std::size_t first = 0,
                             std::size_t count = std::size_t(-1), int subdivisions = 6);
// Distance from p to the quadric surface (Newton projection along the gradient).
double distanceToQuadric(const Quadric& quadric, const Eigen::Vector3d& p);
// The surface point that projection reaches from p.
Eigen::Vector3d closestPointOnQuadric(const Quadric& quadric, const Eigen::Vector3d& p);
// The same for a quadric already normalized (Quadric::normalized, which closestPointOnQuadric
// applies first): the same point, for many points against one quadric.
Eigen::Vector3d closestPointOnNormalizedQuadric(const Quadric& normalized, const Eigen::Vector3d& p);

// Every undirected edge (vertices identified by exact position) is used by exactly two
// triangles, and no triangle is degenerate.
bool isWatertight(const TriangleMesh3& mesh);
// The edges of a mesh by use (vertices identified by exact position): those used by one
// triangle (with that triangle: the mesh's boundary, or a crack), the number used by more
// than two, degenerate triangles (skipped).
struct OpenEdge {
  Eigen::Vector3d a, b;
  std::size_t triangle;
};
struct EdgeUse {
  std::size_t edges = 0;
  std::vector<OpenEdge> open;
  std::size_t overused = 0;
  std::size_t degenerate = 0;
};
EdgeUse edgeUse(const TriangleMesh3& mesh);

// The world-space half-spaces of the camera's view frustum (4 sides widened by 5 %, near and far
// 1e-5 of the depth range inside).
std::vector<HalfSpace> frustumHalfSpaces(const Camera& camera, double aspect);

}  // namespace qacc
