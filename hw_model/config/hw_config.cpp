#include "hw_model/config/hw_config.h"

#include <filesystem>
#include <fstream>
#include <functional>
#include <map>
#include <sstream>
#include <stdexcept>

#include <nlohmann/json.hpp>

#include "modeling/scene/scene_error.h"
#include "modeling/scene/strict_json.h"
#include "modeling/support/bounded_file.h"

namespace qacc {

namespace {

struct Field {
  std::function<void(HwConfig&, const nlohmann::json&, const std::string&)> set;
  std::function<nlohmann::json(const HwConfig&)> get;
};

Field intField(int HwConfig::*m, int lo, int hi) {
  return {[m, lo, hi](HwConfig& c, const nlohmann::json& j, const std::string& where) {
            if (!j.is_number_integer()) throw std::invalid_argument(where + ": expected an integer");
            const long long v = j.get<long long>();
            if (v < lo || v > hi)
              throw std::invalid_argument(where + ": " + std::to_string(v) + " out of range [" + std::to_string(lo) +
                                          ", " + std::to_string(hi) + "]");
            c.*m = int(v);
          },
          [m](const HwConfig& c) { return nlohmann::json(c.*m); }};
}

// A field holding one of two named values: "first" or "second".
template <typename E>
Field choiceField(E HwConfig::*m, const char* first, E a, const char* second, E b) {
  return {[=](HwConfig& c, const nlohmann::json& j, const std::string& where) {
            const std::string s = j.is_string() ? j.get<std::string>() : "";
            if (s == first) c.*m = a;
            else if (s == second) c.*m = b;
            else throw std::invalid_argument(where + ": expected \"" + first + "\" or \"" + second + "\"");
          },
          [=](const HwConfig& c) { return nlohmann::json(c.*m == a ? first : second); }};
}

Field boolField(bool HwConfig::*m) {
  return {[m](HwConfig& c, const nlohmann::json& j, const std::string& where) {
            if (!j.is_boolean()) throw std::invalid_argument(where + ": expected true or false");
            c.*m = j.get<bool>();
          },
          [m](const HwConfig& c) { return nlohmann::json(c.*m); }};
}

const std::map<std::string, Field>& fields() {
  static const std::map<std::string, Field> f = [] {
    std::map<std::string, Field> m;
    m["name"] = {[](HwConfig& c, const nlohmann::json& j, const std::string& w) {
                   if (!j.is_string()) throw std::invalid_argument(w + ": expected a string");
                   c.name = j.get<std::string>();
                 },
                 [](const HwConfig& c) { return nlohmann::json(c.name); }};
    m["clock_mhz"] = {[](HwConfig& c, const nlohmann::json& j, const std::string& w) {
                        if (!j.is_number() || !(j.get<double>() > 0) || j.get<double>() > 1e5)
                          throw std::invalid_argument(w + ": expected a clock in (0, 100000] MHz");
                        c.clock_mhz = j.get<double>();
                      },
                      [](const HwConfig& c) { return nlohmann::json(c.clock_mhz); }};
    m["rounding"] = {[](HwConfig& c, const nlohmann::json& j, const std::string& w) {
                       if (!j.is_string()) throw std::invalid_argument(w + ": expected a string");
                       try {
                         c.rounding = roundingFromString(j.get<std::string>());
                       } catch (const std::exception& e) {
                         throw std::invalid_argument(w + ": " + e.what());
                       }
                     },
                     [](const HwConfig& c) { return nlohmann::json(toString(c.rounding)); }};
    m["overflow"] = {[](HwConfig& c, const nlohmann::json& j, const std::string& w) {
                       if (!j.is_string()) throw std::invalid_argument(w + ": expected a string");
                       try {
                         c.overflow = overflowFromString(j.get<std::string>());
                       } catch (const std::exception& e) {
                         throw std::invalid_argument(w + ": " + e.what());
                       }
                     },
                     [](const HwConfig& c) { return nlohmann::json(toString(c.overflow)); }};
    m["depth_variant"] =
        choiceField(&HwConfig::depth_variant, "stable", DepthVariant::Stable, "reciprocal", DepthVariant::Reciprocal);
    m["shading_normalizer"] = choiceField(&HwConfig::shading_normalizer, "newton", Normalizer::Newton, "recurrence",
                                          Normalizer::Recurrence);
    m["bus_width_bits"] = intField(&HwConfig::bus_width_bits, 8, 1024);
    m["bus_cycles_per_word"] = intField(&HwConfig::bus_cycles_per_word, 1, 64);
    m["descriptor_word_bits"] = intField(&HwConfig::descriptor_word_bits, 8, 64);
    m["host_fifo_depth"] = intField(&HwConfig::host_fifo_depth, 1, 1024);
    m["setup_mad_units"] = intField(&HwConfig::setup_mad_units, 1, 256);
    m["setup_fifo_depth"] = intField(&HwConfig::setup_fifo_depth, 1, 1024);
    m["pipelines"] = intField(&HwConfig::pipelines, 1, 64);
    m["pixel_fifo_depth"] = intField(&HwConfig::pixel_fifo_depth, 1, 4096);
    m["clip_evaluators"] = intField(&HwConfig::clip_evaluators, 1, 64);
    m["value_bits"] = intField(&HwConfig::value_bits, 12, 40);
    m["delta_bits"] = intField(&HwConfig::delta_bits, 16, 80);
    m["interp_frac_bits"] = intField(&HwConfig::interp_frac_bits, 0, 32);
    m["interp_acc_bits"] = intField(&HwConfig::interp_acc_bits, 24, 120);
    m["depth_frac_bits"] = intField(&HwConfig::depth_frac_bits, 12, 36);
    m["depth_bits"] = intField(&HwConfig::depth_bits, 14, 40);
    m["clip_bits"] = intField(&HwConfig::clip_bits, 8, 40);
    m["recip_bits"] = intField(&HwConfig::recip_bits, 8, 48);
    m["zbuffer_bits"] = intField(&HwConfig::zbuffer_bits, 8, 31);
    m["normal_bits"] = intField(&HwConfig::normal_bits, 6, 30);
    m["unit_frac_bits"] = intField(&HwConfig::unit_frac_bits, 6, 28);
    m["color_frac_bits"] = intField(&HwConfig::color_frac_bits, 8, 16);
    m["sqrt_radix"] = intField(&HwConfig::sqrt_radix, 2, 4);
    m["divider_radix"] = intField(&HwConfig::divider_radix, 2, 4);
    m["shading_cycles_per_pixel"] = intField(&HwConfig::shading_cycles_per_pixel, 1, 64);
    m["shading_latency"] = intField(&HwConfig::shading_latency, 1, 256);
    m["zbuffer_banks"] = intField(&HwConfig::zbuffer_banks, 1, 64);
    m["zbuffer_read_latency"] = intField(&HwConfig::zbuffer_read_latency, 1, 64);
    m["zbuffer_bank_busy"] = intField(&HwConfig::zbuffer_bank_busy, 1, 64);
    m["csg_list_depth"] = intField(&HwConfig::csg_list_depth, 1, 1024);
    m["csg_leaf_bits"] = intField(&HwConfig::csg_leaf_bits, 1, 24);
    m["csg_tag_bits"] = intField(&HwConfig::csg_tag_bits, 2, 8);
    m["csg_tile_pruning"] = boolField(&HwConfig::csg_tile_pruning);
    m["hierarchical_z"] = boolField(&HwConfig::hierarchical_z);
    m["hiz_tile_size"] = intField(&HwConfig::hiz_tile_size, 4, 32);
    m["hiz_depth_bits"] = intField(&HwConfig::hiz_depth_bits, 4, 31);
    return m;
  }();
  return f;
}

}  // namespace

HwConfig parseHwConfig(const std::string& text, const std::string& file) {
  nlohmann::json j;
  try {
    j = parseStrictJson(text, file);  // syntax errors with line and column, duplicate keys refused
  } catch (const SceneError& e) {
    throw std::invalid_argument(e.what());
  }
  if (!j.is_object()) throw std::invalid_argument(file + ": /: expected a JSON object");
  const auto format = j.find("format");
  if (format == j.end()) throw std::invalid_argument(file + ": /: missing \"format\" (expected \"" + kHwConfigFormat + "\")");
  if (!format->is_string() || format->get<std::string>() != kHwConfigFormat)
    throw std::invalid_argument(file + ": /format: expected \"" + std::string(kHwConfigFormat) + "\", got " + format->dump());
  HwConfig c;
  if (!j.contains("name") && !file.empty()) c.name = std::filesystem::path(file).stem().string();
  for (auto it = j.begin(); it != j.end(); ++it) {
    if (it.key() == "format") continue;
    if (it.key() == "comment") {
      if (!it.value().is_string()) throw std::invalid_argument(file + ": /comment: expected a string");
      continue;
    }
    setHwConfigKey(c, it.key(), it.value(), file + ": /" + it.key());
  }
  checkHwConfig(c, file);
  return c;
}

void checkHwConfig(const HwConfig& c, const std::string& file) {
  auto fail = [&](const std::string& key, const std::string& why) {
    throw std::invalid_argument(file + ": /" + key + ": " + why);
  };
  if (c.sqrt_radix == 3) fail("sqrt_radix", "radix must be 2 or 4");
  if (c.divider_radix == 3) fail("divider_radix", "radix must be 2 or 4");
  if (c.hiz_tile_size & (c.hiz_tile_size - 1))
    fail("hiz_tile_size", std::to_string(c.hiz_tile_size) + " is not a power of two: the tiles must divide the 32x32 "
                          "traversal tiles (4, 8, 16 or 32)");
  if (c.depth_frac_bits + 2 > c.depth_bits)
    fail("depth_bits", std::to_string(c.depth_bits) + " must exceed depth_frac_bits (" +
                           std::to_string(c.depth_frac_bits) + ") by at least 2: a sign bit and the integer bit of z = 1");
  if (c.zbuffer_bits > c.depth_frac_bits)
    fail("zbuffer_bits", std::to_string(c.zbuffer_bits) + " exceeds depth_frac_bits (" +
                             std::to_string(c.depth_frac_bits) + "): the stored depth would have bits the datapath never computed");
  if (c.delta_bits < 2 * c.value_bits - 8)
    fail("delta_bits", std::to_string(c.delta_bits) + " is below 2 value_bits - 8 (" +
                           std::to_string(2 * c.value_bits - 8) + "): Δ = b² - ac would lose more than the 8 guard bits of its products");
  if (c.interp_acc_bits < c.delta_bits + c.interp_frac_bits + 2)
    fail("interp_acc_bits", std::to_string(c.interp_acc_bits) + " cannot hold delta_bits + interp_frac_bits + 2 (" +
                                std::to_string(c.delta_bits + c.interp_frac_bits + 2) + "): the forward differences would overflow");
  // The shading unit's specular table has 2^unit_frac_bits + 1 entries per material and is
  // built before the first pixel: at unit_frac_bits 28, 1 GiB of 32-bit entries per material.
  if (c.unit_frac_bits > kMaxUnitFracBits)
    fail("unit_frac_bits", std::to_string(c.unit_frac_bits) + " needs a specular table of 2^" +
                               std::to_string(c.unit_frac_bits) + " + 1 entries per material, above the limit of 2^" +
                               std::to_string(kMaxUnitFracBits) + " + 1 (unit vectors of 1." +
                               std::to_string(kMaxUnitFracBits) + " already resolve 1e-6 rad)");
  if (c.unit_frac_bits > c.normal_bits)
    fail("unit_frac_bits", std::to_string(c.unit_frac_bits) + " exceeds normal_bits (" + std::to_string(c.normal_bits) +
                               "): a unit vector cannot carry more fraction bits than the vector it comes from");
}

std::vector<std::string> hwConfigKeys() {
  std::vector<std::string> k;
  for (const auto& f : fields()) k.push_back(f.first);
  return k;
}

bool isHwWidthKey(const std::string& key) {
  static const char* widths[] = {"value_bits", "delta_bits", "interp_frac_bits", "interp_acc_bits", "depth_frac_bits",
                                 "depth_bits", "clip_bits", "recip_bits", "zbuffer_bits", "normal_bits",
                                 "unit_frac_bits", "color_frac_bits"};
  for (const char* w : widths)
    if (key == w) return true;
  return false;
}

bool isHwTimingKey(const std::string& key) {
  // Each is read by timing/ (the units' Params), report/cost_model.cpp, and at most
  // PixelDatapath's count of clip passes (clip_evaluators: PixelTrace::retime) and the CSG
  // pass's tile pruning (csg_tile_pruning: the pass runs in every render). Not here although they change
  // no pixel: hierarchical_z (the setup counts the depth floor's operations when it is on) and
  // depth_variant (another depth datapath).
  static const char* timing[] = {"clock_mhz",        "bus_width_bits",       "bus_cycles_per_word", "descriptor_word_bits",
                                 "host_fifo_depth",  "setup_mad_units",      "setup_fifo_depth",    "pipelines",
                                 "pixel_fifo_depth", "clip_evaluators",      "sqrt_radix",          "divider_radix",
                                 "shading_cycles_per_pixel", "shading_latency", "zbuffer_banks",    "zbuffer_read_latency",
                                 "zbuffer_bank_busy", "csg_tile_pruning",    "hiz_tile_size",       "hiz_depth_bits"};
  for (const char* t : timing)
    if (key == t) return true;
  return false;
}

std::string hwDatapathKey(const HwConfig& c) {
  std::string out;
  for (const auto& [key, field] : fields())
    if (key != "name" && !isHwTimingKey(key)) out += key + "=" + field.get(c).dump() + "\n";
  return out;
}

void setHwConfigKey(HwConfig& c, const std::string& key, const nlohmann::json& value, const std::string& where) {
  const auto f = fields().find(key);
  if (f == fields().end()) throw std::invalid_argument(where + ": unknown accelerator configuration key '" + key + "'");
  f->second.set(c, value, where);
}

nlohmann::json hwConfigValue(const HwConfig& c, const std::string& key) {
  const auto f = fields().find(key);
  if (f == fields().end()) throw std::invalid_argument("unknown accelerator configuration key '" + key + "'");
  return f->second.get(c);
}

HwConfig loadHwConfig(const std::string& path) {
  std::string text;
  try {
    text = readFileBounded(path, kMaxHwConfigBytes, "accelerator configuration");
  } catch (const FileReadError& e) {
    throw std::invalid_argument(path + ": " + e.what());
  }
  return parseHwConfig(text, path);
}

std::string hwConfigToJson(const HwConfig& c) {
  nlohmann::json j = nlohmann::json::object();
  j["format"] = kHwConfigFormat;
  for (const auto& [k, f] : fields()) j[k] = f.get(c);
  return j.dump(2);
}

}  // namespace qacc
