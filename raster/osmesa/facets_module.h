// The facets module: the facet renderer (osmesa_renderer.h) built as a shared module,
// libqacc_facets.so, beside the qacc executable, which loads it only when the facets engine
// draws (tools/engines/facets_module_loader.cpp). Mesa's OSMesa brings libLLVM, z3 and ICU:
// linked into qacc they cost every command about 55 MB of resident memory and 20-60 ms of
// dynamic linking before main (docs/PERFORMANCE.md "Loading Mesa on demand").
//
// The one entry point, with C linkage so that dlsym finds it by this name. Both sides are
// built from the same sources by the same compiler in one build, so the C++ types passed by
// reference are the same; the module binds its own symbols first (-Bsymbolic) and finds the
// rest (the scene, tessellation and shading code) in the executable, which exports them.
#pragma once

#include "raster/osmesa/osmesa_renderer.h"

#include <cstddef>

namespace qacc {
// What the two sides must agree on to pass these types by reference: their sizes and
// alignments, compiled into each side from this header. The loader refuses a module whose
// fingerprint differs (a module left from another build); a changed signature already
// fails in dlopen, by its mangled name.
constexpr std::size_t kFacetsModuleAbi[] = {
    sizeof(Scene),        alignof(Scene),        sizeof(TriangleMesh3),      alignof(TriangleMesh3),
    sizeof(FacetRenderOptions), alignof(FacetRenderOptions), sizeof(FacetRenderResult), alignof(FacetRenderResult),
    sizeof(FrameBuffer),  sizeof(Camera),        sizeof(Primitive),          alignof(Primitive)};
constexpr std::size_t kFacetsModuleAbiSize = sizeof(kFacetsModuleAbi) / sizeof(kFacetsModuleAbi[0]);
}  // namespace qacc

// The module's copy of kFacetsModuleAbi (kFacetsModuleAbiSize values).
extern "C" const std::size_t* qacc_facets_abi();

// Renders as renderFacets does; an exception thrown inside reaches the caller.
extern "C" void qacc_facets_render_v1(const qacc::Scene& scene, const qacc::TriangleMesh3& mesh,
                                      const qacc::FacetRenderOptions& options, qacc::FacetRenderResult& out);
