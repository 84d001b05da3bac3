// The canonical frame of a quadric for the parametric grids (parametric_grid.h).
#pragma once
#include <Eigen/Dense>

#include "modeling/geometry/quadric.h"
#include "modeling/geometry/quadric_type.h"

namespace qacc::tess {

// Canonical frame of a quadric: eigenvectors of the quadratic part (sorted so that the
// axis is the last column), sign normalised so that at least as many eigenvalues are
// positive as negative.
struct Frame {
  Matrix3d E;
  Vector3d g;
  double J = 0;
  Eigen::Vector3d lambda;
  Matrix3d V;
};

Frame canonicalFrame(const Quadric& q);
// Reorder the frame's columns so that column 2 is the eigenvector `axis`.
void putAxisLast(Frame& f, int axis);
// Centre in the span of the non-zero eigenvalues: c = −Σ (vᵢ·g / λᵢ) vᵢ.
Vector3d partialCentre(const Frame& f, double tol);
// The quadric's value in the frame (sign-normalised): xᵀEx + 2g·x + J.
double evalFrame(const Frame& f, const Vector3d& x);
// The canonical frame with, for the axial types (elliptic cylinder and paraboloid: the zero
// eigenvalue; cone and hyperboloids: the negative one), the axis as column 2; *tol is the
// tolerance under which an eigenvalue counts as zero.
Frame axialFrame(const Quadric& q, QuadricType type, double* tol);

}  // namespace qacc::tess
