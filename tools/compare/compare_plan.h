// What `qacc compare` is asked (its options) and what it will run: the scene at its image
// size, the tessellation settings (screen-space tolerances in pixels, the default, or
// triangles-per-primitive levels), the image sizes of the crossover, the facet shading and
// the accelerator configuration.
// Everything the options can get wrong is refused here, before any rendering.
#pragma once
#include "modeling/support/limits.h"
#include <cstddef>
#include <string>
#include <vector>

#include "hw_model/config/hw_config.h"
#include "modeling/scene/scene.h"
#include "raster/pixel/facet_shading.h"

namespace qacc::compare {

struct CompareOptions {
  std::string scene_path;
  std::string tolerances;  // pixels, e.g. "4,2,1,0.5,0.25"; the default when --levels is not given
  std::string levels;      // triangles per primitive, e.g. "8,32,128,512" (excludes --tolerances)
  std::string sizes;       // crossover: "256x192,512x384,..." (the same view at every size)
  std::string out_dir = "compare_out";
  std::string shading = "gouraud";
  std::string config_path;
  int threads = 0;
  int width = 0, height = 0;
  bool no_facet_cycles = false;
  std::size_t max_cycle_triangles = 1000000;  // facet-path cycle runs above this are skipped
  Limits limits;  // loading and tessellation bounds (--max-*)
  bool view_cull = true;  // the loader's view culling (modeling/loader/view_culling.h), at the final size
};

constexpr const char* kDefaultTolerances = "4,2,1,0.5,0.25";

// One tessellation setting: a screen-space tolerance (pixels, view-dependent) or a level.
struct FacetSetting {
  double tolerance_px = 0;  // > 0: every primitive to at most this projected chord error
  int level = 0;            // > 0: triangles per primitive
  std::string label() const;  // "eps 0.5 px" or "level 128"
};

struct ImageSize {
  int width = 0, height = 0;
};

struct ComparePlan {
  Scene scene;
  std::vector<FacetSetting> settings;  // coarse to fine: levels ascending or tolerances descending, distinct
  std::vector<ImageSize> sizes;        // crossover sizes, ascending area (empty: no crossover)
  FacetShading shading = FacetShading::Gouraud;
  HwConfig cfg;
  int zbits = 24;           // depth buffer of the depth-error metric
};

// "8,32,128": integers from 2 to 1000000, sorted, duplicates dropped.
std::vector<int> parseLevels(const std::string& s);
// "4,2,1,0.5": pixels from 0.01 to 1000, sorted coarse (large) to fine, duplicates dropped.
std::vector<double> parseTolerances(const std::string& s);
// "256x192,512x384": sizes from 16x16 to the image-size limit, sorted by area, duplicates dropped.
std::vector<ImageSize> parseSizes(const std::string& s);
// The settings the options ask for: --levels or --tolerances (refused together), else the
// default tolerances.
std::vector<FacetSetting> facetSettings(const CompareOptions& o);

// Loads and sizes the scene, parses the settings, sizes and shading, checks that the facet renderer
// is built in, loads the configuration and creates the output directory.
ComparePlan planCompare(const CompareOptions& o);

}  // namespace qacc::compare
