#include "tools/compare/compare_plan.h"

#include <algorithm>
#include <filesystem>
#include <sstream>
#include <stdexcept>

#include "modeling/loader/scene_loader.h"
#include "raster/osmesa/osmesa_renderer.h"
#include "tools/cli/list_option.h"
#include "tools/engines/engine.h"
#include "tools/engines/image_size.h"

namespace qacc::compare {

std::string FacetSetting::label() const {
  if (level > 0) return "level " + std::to_string(level);
  std::ostringstream s;
  s << "eps " << tolerance_px << " px";
  return s.str();
}

std::vector<int> parseLevels(const std::string& s) {
  std::vector<int> out = parseIntListOption(s, "--levels", "a level", 2, 1000000);
  std::sort(out.begin(), out.end());
  out.erase(std::unique(out.begin(), out.end()), out.end());
  return out;
}

std::vector<double> parseTolerances(const std::string& s) {
  std::vector<double> out = parseDoubleListOption(s, "--tolerances", "a tolerance in pixels", 0.01, 1000);
  std::sort(out.begin(), out.end(), std::greater<double>());
  out.erase(std::unique(out.begin(), out.end()), out.end());
  return out;
}

std::vector<ImageSize> parseSizes(const std::string& s) {
  std::vector<ImageSize> out;
  std::stringstream ss(s);
  std::string item;
  while (std::getline(ss, item, ',')) {
    const auto x = item.find('x');
    if (x == std::string::npos || item.find('x', x + 1) != std::string::npos)
      throw std::invalid_argument("--sizes: '" + item + "' is not a size (WIDTHxHEIGHT, e.g. 640x480)");
    std::string wh = item;
    wh[x] = ',';
    const std::vector<int> v = parseIntListOption(wh, "--sizes", "a side of " + item, 16, kMaxImageSide);
    checkImageSize(v[0], v[1]);
    out.push_back({v[0], v[1]});
  }
  if (out.empty() || s.back() == ',') throw std::invalid_argument("--sizes: nothing given or an empty size");
  std::sort(out.begin(), out.end(), [](const ImageSize& a, const ImageSize& b) {
    return double(a.width) * a.height < double(b.width) * b.height ||
           (double(a.width) * a.height == double(b.width) * b.height && a.width < b.width);
  });
  out.erase(std::unique(out.begin(), out.end(),
                        [](const ImageSize& a, const ImageSize& b) { return a.width == b.width && a.height == b.height; }),
            out.end());
  return out;
}

std::vector<FacetSetting> facetSettings(const CompareOptions& o) {
  if (!o.levels.empty() && !o.tolerances.empty())
    throw std::invalid_argument("--levels and --tolerances exclude each other (levels: triangles per primitive; "
                                "tolerances: pixels of projected chord error)");
  std::vector<FacetSetting> out;
  if (!o.levels.empty()) {
    for (int l : parseLevels(o.levels)) out.push_back({0, l});
  } else {
    for (double t : parseTolerances(o.tolerances.empty() ? kDefaultTolerances : o.tolerances)) out.push_back({t, 0});
  }
  return out;
}

ComparePlan planCompare(const CompareOptions& o) {
  ComparePlan p;
  checkImageSize(o.width, o.height);
  p.scene = loadScene(o.scene_path, o.limits, ViewCulling{o.view_cull, o.width, o.height});
  requireCsgSupport("facets", p.scene);  // the facets half cannot draw CSG yet
  applyImageSize(p.scene, o.width, o.height);
  p.settings = facetSettings(o);
  if (!o.sizes.empty()) {
    if (o.width || o.height)
      throw std::invalid_argument("--sizes and --width/--height exclude each other (--sizes renders every size)");
    if (o.no_facet_cycles)
      throw std::invalid_argument("--sizes needs the facet-path cycles (the crossover compares cycles): drop "
                                  "--no-facet-cycles");
    p.sizes = parseSizes(o.sizes);
  }
  p.shading = parseFacetShading(o.shading);
  requireFacetRenderer();  // before any rendering: a missing facets module is reported first
  p.cfg = o.config_path.empty() ? HwConfig() : loadHwConfig(o.config_path);
  std::filesystem::create_directories(o.out_dir);
  return p;
}

}  // namespace qacc::compare
