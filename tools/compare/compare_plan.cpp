#include "tools/compare/compare_plan.h"

#include <algorithm>
#include <filesystem>
#include <sstream>
#include <stdexcept>

#include "modeling/loader/scene_loader.h"
#include "raster/osmesa/osmesa_renderer.h"
#include "tools/cli/int_list_option.h"
#include "tools/engines/engine.h"
#include "tools/engines/image_size.h"

namespace qacc::compare {

std::vector<int> parseLevels(const std::string& s) {
  std::vector<int> out = parseIntListOption(s, "--levels", "a level", 2, 1000000);
  std::sort(out.begin(), out.end());
  out.erase(std::unique(out.begin(), out.end()), out.end());
  return out;
}

ComparePlan planCompare(const CompareOptions& o) {
  ComparePlan p;
  checkImageSize(o.width, o.height);
  p.scene = loadScene(o.scene_path, o.limits, ViewCulling{o.view_cull, o.width, o.height});
  requireCsgSupport("facets", p.scene);  // the facets half cannot draw CSG yet
  applyImageSize(p.scene, o.width, o.height);
  p.levels = parseLevels(o.levels);
  p.shading = parseFacetShading(o.shading);
  if (!facetRendererAvailable()) throw std::invalid_argument(facetRendererMissingMessage());
  p.cfg = o.config_path.empty() ? HwConfig() : loadHwConfig(o.config_path);
  std::filesystem::create_directories(o.out_dir);
  return p;
}

}  // namespace qacc::compare
