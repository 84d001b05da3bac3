// The parametric grids of the natural quadrics (tessellation.h): ellipsoid (sphere),
// elliptic cylinder, elliptic cone, elliptic paraboloid, hyperboloids of one and two sheets
// get a (u, v) grid in their canonical frame (quadric_frame.h) — u around the axis, v along
// it or the polar angle — whose quads go through the surface builder, which clips them to
// the piece (surface_builder.h).
#pragma once
#include <functional>
#include <vector>

#include <Eigen/Dense>

#include "modeling/geometry/quadric_type.h"
#include "modeling/tessellation/quadric_frame.h"
#include "modeling/tessellation/surface_builder.h"

namespace qacc::tess {

struct Grid {
  int nu = 3, nv = 1;
};

// Grid sizes for a target triangle count.
Grid gridFor(QuadricType type, int target);

// Parametric grid over [0, 2π] x [v0, v1] (u periodic) through the builder; `extra_v` are
// values of v the grid must contain (the apex of a cone).
void emitGrid(SurfaceBuilder& sb, const Grid& g, double v0, double v1, const std::vector<double>& extra_v = {});

// The grid counts of a parametric domain over [0, 2π] x [v0, v1], asked once domain.position
// is set (grid_density.h chooses them from the projected curvature).
using GridChooser = std::function<Grid(double v0, double v1)>;
// Counts for about `target` triangles (gridFor; a cone through its apex splits them
// between its two nappes).
GridChooser gridByTarget(QuadricType type, int target);

// The grid of a natural quadric of `type` over the axial extent of `regionVertices`, with
// the counts `choose` gives; sets domain.position. False when `type` has no parametric grid.
bool emitNaturalQuadricGrid(SurfaceBuilder& sb, Domain& domain, QuadricType type, const Frame& f, double ltol,
                            const std::vector<Vector3d>& regionVertices, const GridChooser& choose);

}  // namespace qacc::tess
