// renderFacets in the qacc executable: the facet renderer lives in the facets module,
// libqacc_facets.so beside the executable (raster/osmesa/facets_module.h), loaded the first
// time the facets engine draws, so that every other command runs without Mesa in memory.
// The test executables link the renderer itself (the qacc_osmesa library) instead of this.
#include <dlfcn.h>
#include <unistd.h>

#include <algorithm>
#include <climits>
#include <stdexcept>
#include <string>

#include "raster/osmesa/facets_module.h"

namespace qacc {
namespace {

using RenderFn = decltype(&qacc_facets_render_v1);
using AbiFn = decltype(&qacc_facets_abi);

std::string modulePath() {
  char buf[PATH_MAX];
  const ssize_t n = readlink("/proc/self/exe", buf, sizeof buf);
  if (n <= 0 || n == ssize_t(sizeof buf))
    throw std::runtime_error("facets: cannot find the qacc executable's directory (/proc/self/exe)");
  std::string exe(buf, std::size_t(n));
  return exe.substr(0, exe.rfind('/') + 1) + "libqacc_facets.so";
}

RenderFn loadRenderer() {
  const std::string path = modulePath();
  // RTLD_NOW: a symbol the module needs and the executable lacks is reported here, by name.
  void* handle = dlopen(path.c_str(), RTLD_NOW | RTLD_LOCAL);
  if (!handle)
    throw std::runtime_error(std::string("facets: cannot load the facets engine's module: ") + dlerror() +
                             " (it is built beside qacc as libqacc_facets.so; keep the two together)");
  void* fn = dlsym(handle, "qacc_facets_render_v1");
  void* abi = dlsym(handle, "qacc_facets_abi");
  if (!fn || !abi) {
    const std::string why = dlerror();
    dlclose(handle);
    throw std::runtime_error("facets: " + path + " is not this qacc's facets module: " + why);
  }
  const std::size_t* theirs = reinterpret_cast<AbiFn>(abi)();
  if (!std::equal(kFacetsModuleAbi, kFacetsModuleAbi + kFacetsModuleAbiSize, theirs)) {
    dlclose(handle);
    throw std::runtime_error("facets: " + path +
                             " was built from other sources than this qacc (its types' layouts differ): rebuild both");
  }
  return reinterpret_cast<RenderFn>(fn);
}

RenderFn renderer() {
  static const RenderFn render = loadRenderer();  // once; a failed load is retried and reported again
  return render;
}

}  // namespace

void prepareFacetRenderer() { renderer(); }

FacetRenderResult renderFacets(const Scene& scene, const TriangleMesh3& mesh, const FacetRenderOptions& options) {
  FacetRenderResult out;
  renderer()(scene, mesh, options, out);
  return out;
}

}  // namespace qacc
