// A shipped CSG scene (scenes/csg/NAME.json) loaded and resized for the accelerator's tests.
#pragma once
#include <string>

#include "modeling/loader/scene_loader.h"

inline qacc::Scene csgScene(const std::string& name, int w, int h) {
  qacc::Scene s = qacc::loadScene(std::string(QACC_SOURCE_DIR) + "/scenes/csg/" + name + ".json");
  s.width = w;
  s.height = h;
  return s;
}
