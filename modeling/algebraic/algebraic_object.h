// Scene object "algebraic" (design §5-6): an algebraic surface of any degree, approximated
// by quadric pieces (degree_reduction_model.h) and drawn by the reference renderer from the
// true surface (algebraic_surface.h).
//
//   {"type": "algebraic", "poly": "x^4 + y^4 + z^4 - 1", "box": [[-1.2,-1.2,-1.2],[1.2,1.2,1.2]],
//    "level": 4, "refine_error": 0.01, "max_level": 64, "smooth": false, "merge": false,
//    "cull": true, "params": {"R": 1, "r": 0.4}, "reference": "exact"}
//
// poly: the polynomial f (interior f <= 0), with named constants from "params"; box: the
// region modelled (the surface is clipped to it); level: cubes per axis of the Kuhn mesh
// (1..256, default 4); refine_error (optional, world units): refine 1 → 8 until the
// sampled geometric error is below it, up to max_level cubes per axis (default 64);
// smooth, merge: see degree_reduction_model.h; cull (default true) can be turned off to
// check that culling changes nothing; reference: "exact" (default: the reference renderer
// ray-casts the true surface) or "pieces" (it renders the quadric pieces exactly).
#pragma once
#include <vector>

#include "modeling/algebraic/degree_reduction.h"
#include "modeling/loader/object_registry.h"
#include "modeling/algebraic/polynomial3.h"

namespace qacc {

// The keys of an "algebraic" object, validated (for the builder and the study command).
struct AlgebraicSpec {
  Polynomial3 f;
  Eigen::AlignedBox3d box;
  DegreeReductionOptions options;
  bool exact_reference = true;  // "reference": "exact"
};
AlgebraicSpec readAlgebraicSpec(const JsonNode& o);

std::vector<Primitive> buildAlgebraic(const JsonNode& o, ObjectContext& ctx);

}  // namespace qacc
