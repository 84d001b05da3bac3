#include "tools/bench/sphere_grid_scene.h"

#include <cmath>
#include <cstdio>

namespace qacc {

std::string sphereGridScene(std::size_t n) {
  std::string text =
      "{\"format\": \"qacc-scene/1\", \"name\": \"sphere_grid_" + std::to_string(n) +
      "\",\n \"image\": {\"width\": 320, \"height\": 240},\n"
      " \"camera\": {\"type\": \"perspective\", \"eye\": [0, 0, 5], \"target\": [0, 0, 0], \"up\": [0, 1, 0], "
      "\"fov_y_deg\": 30, \"near\": 1, \"far\": 10},\n"
      " \"objects\": [\n";
  const std::size_t side = std::size_t(std::ceil(std::sqrt(double(n))));
  const double step = 2.0 / double(side);
  text.reserve(text.size() + n * 72 + 8);
  char line[128];
  for (std::size_t i = 0; i < n; ++i) {
    const double x = -1 + step * (double(i % side) + 0.5), y = -1 + step * (double(i / side) + 0.5);
    const int len = std::snprintf(line, sizeof line, "%s{\"type\": \"sphere\", \"center\": [%.6f, %.6f, 0], \"radius\": 0.01}",
                                  i ? ",\n" : "", x, y);
    text.append(line, std::size_t(len));
  }
  text += "]}\n";
  return text;
}

}  // namespace qacc
