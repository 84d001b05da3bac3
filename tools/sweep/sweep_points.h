// The points of a sweep, in a deterministic order, and the share of them a shard runs.
// Grid: the Cartesian product of the axes, the first axis varying slowest. One axis at a
// time ("mode": "one_axis"): the base point first, then each axis's settings with every
// other axis at the base (settings equal to the base are not repeated).
// A work item is one (point, scene): item = point x scenes + scene. Shard I/N (1-based I)
// runs the items with item % N == I - 1.
#pragma once
#include <cstddef>
#include <string>
#include <vector>

#include <nlohmann/json.hpp>

#include "tools/sweep/sweep_spec.h"

namespace qacc {

struct SweepPoint {
  std::size_t index = 0;
  std::string label;            // "base" or the settings ("value_bits=24 delta_bits=48")
  HwConfig config;              // base + the settings
  nlohmann::ordered_json knobs = nlohmann::ordered_json::object();  // scene.* values of this point
  std::string refused;          // non-empty: the configuration is refused, with the reason
};

std::vector<SweepPoint> sweepPoints(const SweepSpec& spec);

struct Shard {
  int index = 1, count = 1;  // this is shard `index` of `count` (1-based)
  bool takes(std::size_t item) const { return int(item % std::size_t(count)) == index - 1; }
  std::string text() const { return std::to_string(index) + "/" + std::to_string(count); }
};
// "I/N" with 1 <= I <= N; throws std::invalid_argument otherwise.
Shard parseShard(const std::string& s);

}  // namespace qacc
