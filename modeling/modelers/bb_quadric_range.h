// The exact range of a BB quadric on its closed tetrahedron: a safe emptiness test stronger
// than the Bernstein sign test (BBQuadric::isProvablyEmpty).
//
// f(λ) = λᵀ C λ on the simplex λ >= 0, Σ λ = 1 (bb_quadric.h). Its minimum and maximum lie at
// a critical point of f restricted to the relative interior of one of the simplex's 15 faces
// (4 vertices, 6 edges, 4 triangles, the tetrahedron itself): for a face S, C_SS λ = μ 1,
// 1ᵀ λ = 1, with λ > 0 (Lagrange). Where that system is singular f is flat along a line of
// the face, so its extremes on the face are reached on the face's boundary, a smaller face.
// Each candidate's value is a value f takes in the tetrahedron, so min/max over the
// candidates is the range, up to rounding of O(1e-15 · |C| · condition). `isEmptyExactly`
// calls a cell empty only when the range misses 0 by more than 1e-9 · max |C|.
//
// The sign test sees only the 10 coefficients, which bound f by the convex hull property;
// this test sees the values themselves: every cell the sign test calls empty, it calls
// empty too, and it also catches cells whose coefficients change sign while f does not
// (docs/DEGREE_REDUCTION.md, "The emptiness tests measured").
#pragma once

#include "modeling/modelers/bb_quadric.h"

namespace qacc {

struct QuadricRange {
  double min = 0, max = 0;
};

// The range of f = λᵀ C λ over the closed tetrahedron.
QuadricRange rangeOnTetrahedron(const BBQuadric& q);
// True only when f has one strict sign on the closed tetrahedron, by a margin of 1e-9 max |C|.
bool isEmptyExactly(const BBQuadric& q);

}  // namespace qacc
