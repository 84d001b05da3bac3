#include "hw_model/report/hw_stats.h"

#include <cmath>
#include <cstdio>
#include <fstream>
#include <sstream>
#include <stdexcept>

#include <nlohmann/json.hpp>

namespace qacc {

void PixelCounters::add(const PixelCounters& o) {
  tested += o.tested;
  covered += o.covered;
  caps += o.caps;
  clipped += o.clipped;
  depth_rejected += o.depth_rejected;
  written += o.written;
  clip_passes += o.clip_passes;
}

double HwStats::overdraw() const {
  return distinct_written ? double(pixels.covered) / double(distinct_written) : 0.0;
}

namespace {

nlohmann::ordered_json toJ(const HwStats& s) {
  nlohmann::ordered_json j;
  j["format"] = "qacc-hw-stats/1";
  j["engine"] = s.engine;
  j["config"] = s.config;
  j["scene"] = s.scene;
  j["width"] = s.width;
  j["height"] = s.height;
  j["threads"] = s.threads;
  j["primitives"] = s.primitives;
  j["visible_primitives"] = s.visible_primitives;
  j["facet_primitives"] = s.facet_primitives;
  j["pixels"] = {{"tested", s.pixels.tested},           {"covered", s.pixels.covered},
                 {"caps", s.pixels.caps},               {"clipped", s.pixels.clipped},
                 {"depth_rejected", s.pixels.depth_rejected}, {"written", s.pixels.written},
                 {"clip_passes", s.pixels.clip_passes}, {"distinct_written", s.distinct_written}};
  j["overdraw"] = s.overdraw();
  j["overflows"] = {{"total", s.overflow.total()},
                    {"setup", s.overflow.setup.events},
                    {"interpolator", s.overflow.interpolator.events},
                    {"sqrt", s.overflow.sqrt.events},
                    {"depth", s.overflow.depth.events},
                    {"clip", s.overflow.clip.events},
                    {"shading", s.overflow.shading.events},
                    {"depth_clamps", s.overflow.depth_clamps}};
  j["cycles"] = s.cycles;
  j["fast_forwarded_cycles"] = s.fast_forwarded;
  j["clock_mhz"] = s.clock_mhz;
  const double ft = s.frameSeconds();
  j["frame_time_ms"] = ft * 1e3;
  j["fps"] = ft > 0 ? 1.0 / ft : 0.0;
  j["quadrics_per_second"] = ft > 0 ? double(s.visible_primitives) / ft : 0.0;
  j["pixels_per_second"] = ft > 0 ? double(s.pixels.covered) / ft : 0.0;
  j["host_seconds"] = s.host_seconds;
  j["host_cycles_per_second"] = s.host_seconds > 0 ? double(s.cycles) / s.host_seconds : 0.0;
  j["slowdown"] = ft > 0 ? s.host_seconds / ft : 0.0;
  j["loop_seconds"] = s.loop_seconds;
  j["loop_cycles_per_second"] = s.loop_seconds > 0 ? double(s.cycles) / s.loop_seconds : 0.0;
  j["trace_seconds"] = s.trace_seconds;
  nlohmann::ordered_json units = nlohmann::ordered_json::array();
  for (const auto& u : s.units)
    units.push_back({{"name", u.name}, {"busy", u.busy}, {"stall", u.stall}, {"idle", u.idle}, {"items", u.items}});
  j["units"] = units;
  nlohmann::ordered_json cost = nlohmann::ordered_json::array();
  for (const UnitCost& u : s.cost.units)
    cost.push_back({{"name", u.unit}, {"copies", u.copies}, {"ge_each", u.ge_each}, {"rom_bits", u.rom_bits}});
  j["cost"] = {{"total_ge", s.cost.totalGe()}, {"zbuffer_bits_per_pixel", s.cost.zbufferBitsPerPixel}, {"units", cost}};
  return j;
}

void flatten(const nlohmann::ordered_json& j, const std::string& prefix, std::vector<std::string>& keys,
             std::vector<std::string>& values) {
  for (auto it = j.begin(); it != j.end(); ++it) {
    const std::string k = prefix.empty() ? it.key() : prefix + "." + it.key();
    if (it->is_object()) {
      flatten(*it, k, keys, values);
    } else if (it->is_array()) {
      for (const auto& u : *it) {
        const std::string p = k + "." + u["name"].get<std::string>();
        for (auto f = u.begin(); f != u.end(); ++f) {
          if (f.key() == "name") continue;
          keys.push_back(p + "." + f.key());
          values.push_back(f->dump());
        }
      }
    } else {
      keys.push_back(k);
      values.push_back(it->is_string() ? it->get<std::string>() : it->dump());
    }
  }
}

}  // namespace

std::string HwStats::toJson() const { return toJ(*this).dump(2) + "\n"; }

std::string HwStats::toCsv() const {
  std::vector<std::string> keys, values;
  flatten(toJ(*this), "", keys, values);
  std::string a, b;
  for (std::size_t i = 0; i < keys.size(); ++i) {
    a += (i ? "," : "") + keys[i];
    b += (i ? "," : "") + values[i];
  }
  return a + "\n" + b + "\n";
}

void HwStats::write(const std::string& path) const {
  std::ofstream j(path);
  if (!j) throw std::invalid_argument(path + ": cannot write statistics");
  j << toJson();
  std::string csv = path;
  const auto dot = csv.find_last_of('.');
  const auto slash = csv.find_last_of('/');
  if (dot != std::string::npos && (slash == std::string::npos || dot > slash)) csv.resize(dot);
  csv += ".csv";
  std::ofstream c(csv);
  if (!c) throw std::invalid_argument(csv + ": cannot write statistics");
  c << toCsv();
}

std::vector<std::string> HwStats::summaryLines() const {
  std::vector<std::string> out;
  char buf[512];
  std::snprintf(buf, sizeof buf,
                "%s [%s]: %llu pixels tested, %llu covered (%llu caps), %llu clipped, %llu depth-rejected, %llu written, overdraw %.2f, overflows %llu",
                engine.c_str(), config.c_str(), (unsigned long long)pixels.tested, (unsigned long long)pixels.covered,
                (unsigned long long)pixels.caps, (unsigned long long)pixels.clipped,
                (unsigned long long)pixels.depth_rejected, (unsigned long long)pixels.written, overdraw(),
                (unsigned long long)overflow.total());
  out.push_back(buf);
  if (cycles > 0) {
    const double ft = frameSeconds();
    std::snprintf(buf, sizeof buf,
                  "cycles %llu at %.1f MHz: frame %.3f ms (%.1f fps), %.3g quadrics/s, %.3g pixels/s; host %.3f s, %.3g simulated cycles/s (timing loop alone %.3g; pixel datapath pass %.3f s), slowdown %.0fx",
                  (unsigned long long)cycles, clock_mhz, ft * 1e3, ft > 0 ? 1.0 / ft : 0.0,
                  ft > 0 ? double(visible_primitives) / ft : 0.0, ft > 0 ? double(pixels.covered) / ft : 0.0,
                  host_seconds, host_seconds > 0 ? double(cycles) / host_seconds : 0.0,
                  loop_seconds > 0 ? double(cycles) / loop_seconds : 0.0, trace_seconds, ft > 0 ? host_seconds / ft : 0.0);
    out.push_back(buf);
  }
  std::string cost = "silicon (cost model): " + std::to_string(int(std::lround(this->cost.totalGe() / 1e3))) + " kGE =";
  for (std::size_t i = 0; i < this->cost.units.size(); ++i) {
    const UnitCost& u = this->cost.units[i];
    std::snprintf(buf, sizeof buf, "%s %s %s%.1f", i ? " +" : "", u.unit.c_str(),
                  u.copies > 1 ? (std::to_string(u.copies) + " x ").c_str() : "", u.ge_each / 1e3);
    cost += buf;
  }
  out.push_back(cost + " kGE; Z-buffer memory off-chip, " + std::to_string(int(this->cost.zbufferBitsPerPixel)) +
                " bits per pixel");
  return out;
}

}  // namespace qacc
