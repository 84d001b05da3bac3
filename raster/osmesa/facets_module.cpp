#include "raster/osmesa/facets_module.h"

extern "C" __attribute__((visibility("default"))) void qacc_facets_render_v1(const qacc::Scene& scene,
                                                                            const qacc::TriangleMesh3& mesh,
                                                                            const qacc::FacetRenderOptions& options,
                                                                            qacc::FacetRenderResult& out) {
  out = qacc::renderFacets(scene, mesh, options);
}

extern "C" __attribute__((visibility("default"))) const std::size_t* qacc_facets_abi() { return qacc::kFacetsModuleAbi; }
