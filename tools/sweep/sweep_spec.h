// SweepSpec: a `qacc sweep` specification (`qacc-sweep/1` JSON, docs/SWEEP.md), read
// strictly: every problem is refused as "SPEC: /json/path: problem". A spec names the
// scenes, the engine, the base configuration and scene knobs, and the axes; each axis
// varies accelerator configuration keys or scene knobs:
//   {"key": "value_bits", "values": [32, 24, 16]}
//   {"key": "value_bits", "range": [32, 16, -2]}          from, to (inclusive), step
//   {"name": "all_widths", "settings": [{"value_bits": 24, "delta_bits": 48}, ...]}
// Scene knobs are keys with the prefix "scene.": scene.size ([w, h]),
// scene.tessellation_level (the scene's triangles through the accelerator's facet path),
// scene.tessellation_tolerance (the same, refined to this chord error in world units),
// scene.reduction_level (degree-reduction level of every algebraic object) and
// scene.macropatch ("G0" | "G1", the model of every macropatch object).
#pragma once
#include <map>
#include <string>
#include <vector>

#include <nlohmann/json.hpp>

#include "hw_model/config/hw_config.h"

namespace qacc {

// One value of an axis: the keys it sets (configuration keys and scene.* knobs) and a label.
struct AxisSetting {
  std::string label;  // "value_bits=24", or the setting's "label"
  nlohmann::ordered_json set = nlohmann::ordered_json::object();
};

struct SweepAxis {
  std::string name;  // the key, or the axis "name"
  std::vector<AxisSetting> settings;
};

struct SweepSpec {
  std::string file;         // the spec file (messages, relative paths)
  nlohmann::ordered_json json;  // the spec as read
  std::string name;
  std::vector<std::string> scenes;  // resolved paths
  std::string engine = "hw-cycle";  // hw | hw-cycle
  HwConfig base;                     // base configuration
  nlohmann::ordered_json base_knobs = nlohmann::ordered_json::object();  // scene.* of the base point
  bool grid = true;                  // "mode": "grid" | "one_axis"
  std::vector<SweepAxis> axes;
  std::string target;                // optional "wrong<=0.1%,pinholes=0": the answer the report states
  int thumbnail_width = 160;         // 0: no thumbnails
  std::string hash;                  // content hash of the spec text (shards and merge must agree)
};

SweepSpec loadSweepSpec(const std::string& path);
SweepSpec parseSweepSpec(const std::string& text, const std::string& file, const std::string& directory);

// Knob names, and whether a key is a scene knob.
bool isSceneKnob(const std::string& key);
const std::vector<std::string>& sceneKnobNames();  // "scene.size", ...

}  // namespace qacc
