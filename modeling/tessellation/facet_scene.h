// The triangles of a tessellated scene as primitives (planes clipped by their 3 edge
// half-spaces, design §2), so that the accelerator's flat-facet path can draw exactly the
// triangles the facet renderer draws and report their cycle counts.
#pragma once
#include "modeling/scene/scene.h"
#include "modeling/tessellation/tessellation.h"

namespace qacc {

// A copy of `scene` whose primitives are the mesh's triangles (object and material kept,
// degenerate triangles dropped; objects keep their exact surfaces off: every renderer draws
// the facets).
Scene facetScene(const Scene& scene, const TriangleMesh3& mesh);

}  // namespace qacc
