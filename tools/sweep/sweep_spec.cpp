#include "tools/sweep/sweep_spec.h"

#include <cstdio>
#include <filesystem>
#include <fstream>
#include <memory>
#include <sstream>
#include <stdexcept>

#include "modeling/scene/json_node.h"
#include "modeling/scene/scene_error.h"

namespace qacc {

namespace fs = std::filesystem;

const std::vector<std::string>& sceneKnobNames() {
  static const std::vector<std::string> k = {"scene.size", "scene.tessellation_level", "scene.tessellation_tolerance",
                                             "scene.reduction_level", "scene.macropatch"};
  return k;
}

bool isSceneKnob(const std::string& key) {
  for (const auto& k : sceneKnobNames())
    if (k == key) return true;
  return false;
}

namespace {

std::string valueText(const nlohmann::ordered_json& v) { return v.is_string() ? v.get<std::string>() : v.dump(); }

// Checks one key = value of a setting (a configuration key on a scratch configuration, or a knob).
void checkSetting(const JsonNode& node, const std::string& key) {
  if (isSceneKnob(key)) {
    const nlohmann::json& v = node.json();
    if (key == "scene.size") {
      if (!v.is_array() || v.size() != 2 || !v[0].is_number_integer() || !v[1].is_number_integer() ||
          v[0].get<long long>() < 8 || v[1].get<long long>() < 8 || v[0].get<long long>() > 8192 ||
          v[1].get<long long>() > 8192)
        node.fail("scene.size: expected [width, height], integers in [8, 8192]");
    } else if (key == "scene.tessellation_level") {
      node.integer(2, 1000000);
    } else if (key == "scene.tessellation_tolerance") {
      node.positive();
    } else if (key == "scene.reduction_level") {
      node.integer(1, 256);
    } else if (key == "scene.macropatch") {
      const std::string s = node.string();
      if (s != "G0" && s != "G1") node.fail("scene.macropatch: expected \"G0\" or \"G1\"");
    }
    return;
  }
  HwConfig scratch;
  try {
    setHwConfigKey(scratch, key, node.json(), node.file() + ": " + node.path());
  } catch (const std::invalid_argument& e) {
    throw std::invalid_argument(e.what());
  }
}

AxisSetting settingOf(const std::string& key, const JsonNode& value) {
  checkSetting(value, key);
  AxisSetting s;
  s.set[key] = value.json();
  s.label = key + "=" + valueText(value.json());
  return s;
}

SweepAxis readAxis(const JsonNode& a) {
  SweepAxis axis;
  if (a.has("settings")) {
    axis.name = a.at("name").string();
    const JsonNode list = a.at("settings");
    if (list.size() == 0) list.fail("expected at least one setting");
    for (std::size_t i = 0; i < list.size(); ++i) {
      const JsonNode st = list[i];
      if (!st.isObject()) st.fail("expected an object of keys and values");
      AxisSetting s;
      std::string label;
      for (auto it = st.json().begin(); it != st.json().end(); ++it) {
        if (it.key() == "label") {
          s.label = st.at("label").string();
          continue;
        }
        const JsonNode v = st.at(it.key());
        checkSetting(v, it.key());
        s.set[it.key()] = it.value();
        label += (label.empty() ? "" : ",") + it.key() + "=" + valueText(it.value());
      }
      if (s.set.empty()) st.fail("a setting must set at least one key");
      if (s.label.empty()) s.label = label;
      axis.settings.push_back(s);
    }
    a.finish();
    return axis;
  }
  axis.name = a.at("key").string();
  if (a.has("values") == a.has("range")) a.fail("an axis has either \"values\" or \"range\" (or \"name\" and \"settings\")");
  if (a.has("values")) {
    const JsonNode list = a.at("values");
    if (list.size() == 0) list.fail("expected at least one value");
    for (std::size_t i = 0; i < list.size(); ++i) axis.settings.push_back(settingOf(axis.name, list[i]));
  } else {
    const JsonNode r = a.at("range");
    if (r.size() != 3) r.fail("expected [from, to, step]");
    const long long from = r[0].integer(-1000000, 1000000), to = r[1].integer(-1000000, 1000000),
                    step = r[2].integer(-1000000, 1000000);
    if (step == 0 || (to - from) / step < 0) r[2].fail("the step must be non-zero and lead from 'from' to 'to'");
    if ((to - from) / step > 10000) r.fail("more than 10000 values");
    for (long long v = from; step > 0 ? v <= to : v >= to; v += step) {
      const nlohmann::json value = v;
      const JsonNode node(value, r.path(), std::make_shared<const std::string>(r.file()));
      axis.settings.push_back(settingOf(axis.name, node));
    }
  }
  a.finish();
  return axis;
}

}  // namespace

SweepSpec parseSweepSpec(const std::string& text, const std::string& file, const std::string& directory) {
  SweepSpec spec;
  spec.file = file;
  nlohmann::json j;
  try {
    j = nlohmann::json::parse(text);
  } catch (const std::exception& e) {
    throw std::invalid_argument(file + ": JSON syntax error: " + e.what());
  }
  spec.json = nlohmann::ordered_json::parse(text);
  const JsonNode root(j, "", std::make_shared<const std::string>(file));
  if (!root.isObject()) root.fail("expected a JSON object");
  if (root.at("format").string() != "qacc-sweep/1") root.at("format").fail("expected \"qacc-sweep/1\"");
  spec.name = root.string("name", fs::path(file).stem().string());
  root.string("description", "");
  const JsonNode scenes = root.at("scenes");
  if (scenes.size() == 0) scenes.fail("expected at least one scene");
  for (std::size_t i = 0; i < scenes.size(); ++i) {
    const std::string s = scenes[i].string();
    const fs::path p = fs::path(s).is_absolute() ? fs::path(s) : fs::path(directory) / s;
    std::error_code ec;
    if (!fs::is_regular_file(p, ec)) scenes[i].fail("no such scene file: " + p.string());
    spec.scenes.push_back(p.lexically_normal().string());
  }
  spec.engine = root.string("engine", "hw-cycle");
  if (spec.engine != "hw" && spec.engine != "hw-cycle")
    root.at("engine").fail("expected \"hw\" or \"hw-cycle\" (hw-cycle also measures cycles)");
  const std::string mode = root.string("mode", "grid");
  if (mode != "grid" && mode != "one_axis") root.at("mode").fail("expected \"grid\" or \"one_axis\"");
  spec.grid = mode == "grid";
  if (auto b = root.get("base")) {
    if (b->json().is_string()) {
      const std::string s = b->string();
      const fs::path p = fs::path(s).is_absolute() ? fs::path(s) : fs::path(directory) / s;
      try {
        spec.base = loadHwConfig(p.string());
      } catch (const std::invalid_argument& e) {
        b->fail(e.what());
      }
    } else {
      if (!b->isObject()) b->fail("expected a configuration file name or an object of keys");
      spec.base.name = "base";
      for (auto it = b->json().begin(); it != b->json().end(); ++it) {
        const JsonNode v = b->at(it.key());
        if (isSceneKnob(it.key())) {
          checkSetting(v, it.key());
          spec.base_knobs[it.key()] = it.value();
        } else if (it.key() == "name") {
          spec.base.name = v.string();
        } else {
          checkSetting(v, it.key());
          setHwConfigKey(spec.base, it.key(), it.value(), file + ": /base/" + jsonPointerKey(it.key()));
        }
      }
      try {
        checkHwConfig(spec.base, file + ": /base");
      } catch (const std::invalid_argument& e) {
        throw std::invalid_argument(e.what());
      }
    }
  }
  if (auto sz = root.get("size")) {
    checkSetting(*sz, "scene.size");
    spec.base_knobs["scene.size"] = sz->json();
  }
  const JsonNode axes = root.at("axes");
  for (std::size_t i = 0; i < axes.size(); ++i) spec.axes.push_back(readAxis(axes[i]));
  spec.target = root.string("target", "");
  if (auto t = root.get("thumbnail_width")) spec.thumbnail_width = int(t->integer(0, 640));
  root.finish();
  char buf[20];
  std::uint64_t h = 1469598103934665603ULL;
  for (unsigned char c : text) h = (h ^ c) * 1099511628211ULL;
  std::snprintf(buf, sizeof buf, "%016llx", (unsigned long long)h);
  spec.hash = buf;
  return spec;
}

SweepSpec loadSweepSpec(const std::string& path) {
  std::ifstream in(path);
  if (!in) throw std::invalid_argument(path + ": cannot open sweep specification");
  std::stringstream ss;
  ss << in.rdbuf();
  const fs::path p(path);
  return parseSweepSpec(ss.str(), path, p.has_parent_path() ? p.parent_path().string() : ".");
}

}  // namespace qacc
