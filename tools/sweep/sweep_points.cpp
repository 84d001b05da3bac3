#include "tools/sweep/sweep_points.h"

#include <stdexcept>

namespace qacc {

namespace {

SweepPoint applySettings(const SweepSpec& spec, const std::vector<const AxisSetting*>& settings) {
  SweepPoint p;
  p.config = spec.base;
  p.knobs = spec.base_knobs;
  std::string label;
  for (const AxisSetting* s : settings) {
    label += (label.empty() ? "" : " ") + s->label;
    for (auto it = s->set.begin(); it != s->set.end(); ++it) {
      if (isSceneKnob(it.key())) p.knobs[it.key()] = it.value();
      else setHwConfigKey(p.config, it.key(), it.value(), spec.file);  // checked when the spec was read
    }
  }
  p.label = label.empty() ? "base" : label;
  p.config.name = spec.name + "[" + p.label + "]";
  try {
    checkHwConfig(p.config, p.label);
  } catch (const std::invalid_argument& e) {
    p.refused = e.what();
  }
  return p;
}

bool sameAsBase(const SweepSpec& spec, const AxisSetting& s) {
  for (auto it = s.set.begin(); it != s.set.end(); ++it) {
    if (isSceneKnob(it.key())) {
      if (!spec.base_knobs.contains(it.key()) || spec.base_knobs[it.key()] != it.value()) return false;
    } else if (nlohmann::ordered_json(hwConfigValue(spec.base, it.key())) != it.value()) {
      return false;
    }
  }
  return true;
}

}  // namespace

std::vector<SweepPoint> sweepPoints(const SweepSpec& spec) {
  std::vector<SweepPoint> out;
  if (spec.grid) {
    std::size_t total = 1;
    for (const SweepAxis& axis : spec.axes) {
      total *= axis.settings.size();
      if (total > 100000) throw std::invalid_argument(spec.file + ": /axes: the grid has more than 100000 points");
    }
    for (std::size_t n = 0; n < total; ++n) {
      std::vector<const AxisSetting*> s(spec.axes.size());
      std::size_t r = n;
      for (std::size_t a = spec.axes.size(); a-- > 0;) {
        s[a] = &spec.axes[a].settings[r % spec.axes[a].settings.size()];
        r /= spec.axes[a].settings.size();
      }
      out.push_back(applySettings(spec, s));
    }
  } else {
    out.push_back(applySettings(spec, {}));
    for (const SweepAxis& axis : spec.axes)
      for (const AxisSetting& s : axis.settings)
        if (!sameAsBase(spec, s)) out.push_back(applySettings(spec, {&s}));
  }
  for (std::size_t i = 0; i < out.size(); ++i) out[i].index = i;
  return out;
}

Shard parseShard(const std::string& s) {
  const auto slash = s.find('/');
  Shard sh;
  std::size_t p1 = 0, p2 = 0;
  try {
    if (slash == std::string::npos) throw std::invalid_argument("");
    sh.index = std::stoi(s.substr(0, slash), &p1);
    sh.count = std::stoi(s.substr(slash + 1), &p2);
  } catch (...) {
    p1 = 0;
  }
  if (slash == std::string::npos || p1 != slash || p2 != s.size() - slash - 1 || sh.count < 1 || sh.index < 1 ||
      sh.index > sh.count)
    throw std::invalid_argument("--shard: '" + s + "' is not I/N with 1 <= I <= N");
  return sh;
}

}  // namespace qacc
