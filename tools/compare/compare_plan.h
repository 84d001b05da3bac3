// What `qacc compare` is asked (its options) and what it will run: the scene at its image
// size, the tessellation levels, the facet shading and the accelerator configuration.
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
  std::string levels = "8,32,128,512";
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

struct ComparePlan {
  Scene scene;
  std::vector<int> levels;  // ascending, distinct
  FacetShading shading = FacetShading::Gouraud;
  HwConfig cfg;
  int zbits = 24;           // depth buffer of the depth-error metric
};

// "8,32,128": integers from 2 to 1000000, sorted, duplicates dropped.
std::vector<int> parseLevels(const std::string& s);

// Loads and sizes the scene, parses the levels and shading, checks that the facet renderer
// is built in, loads the configuration and creates the output directory.
ComparePlan planCompare(const CompareOptions& o);

}  // namespace qacc::compare
