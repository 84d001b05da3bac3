#include "tools/compare/compare_plan.h"

#include <algorithm>
#include <filesystem>
#include <sstream>
#include <stdexcept>

#include "modeling/loader/scene_loader.h"
#include "raster/osmesa/osmesa_renderer.h"
#include "tools/engines/engine.h"
#include "tools/engines/image_size.h"

namespace qacc::compare {

std::vector<int> parseLevels(const std::string& s) {
  std::vector<int> out;
  std::stringstream ss(s);
  std::string item;
  while (std::getline(ss, item, ',')) {
    if (item.empty()) continue;
    std::size_t pos = 0;
    int v = 0;
    try {
      v = std::stoi(item, &pos);
    } catch (...) {
      pos = 0;
    }
    if (pos != item.size() || v < 2 || v > 1000000)
      throw std::invalid_argument("--levels: '" + item + "' is not a level (an integer from 2 to 1000000)");
    out.push_back(v);
  }
  if (out.empty()) throw std::invalid_argument("--levels: no level given");
  std::sort(out.begin(), out.end());
  out.erase(std::unique(out.begin(), out.end()), out.end());
  return out;
}

ComparePlan planCompare(const CompareOptions& o) {
  ComparePlan p;
  p.scene = loadScene(o.scene_path, o.limits);
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
