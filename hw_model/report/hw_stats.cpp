#include "hw_model/report/hw_stats.h"

#include <algorithm>

#include <cmath>
#include <cstdio>
#include <fstream>
#include <sstream>
#include <stdexcept>

#include <nlohmann/json.hpp>

#include "hw_model/datapath/csg_interval_list.h"
#include "hw_model/datapath/hierarchical_z_memory.h"
#include "hw_model/report/stats_file.h"

namespace qacc {

void CsgCounters::add(const CsgCounters& o) {
  objects = std::max(objects, o.objects);
  leaf_pixels += o.leaf_pixels;
  interval_ends += o.interval_ends;
  max_list_ends = std::max(max_list_ends, o.max_list_ends);
  resolved += o.resolved;
  overflowed_pixels += o.overflowed_pixels;
  dropped_intervals += o.dropped_intervals;
  leaves_tested += o.leaves_tested;
  leaves_pruned += o.leaves_pruned;
  products_pruned += o.products_pruned;
  jobs_pruned += o.jobs_pruned;
  cycles += o.cycles;
}

std::string CsgCounters::line(const HwConfig& cfg) const {
  char buf[512];
  std::snprintf(buf, sizeof buf,
                "csg: %llu objects, %llu leaf-pixel evaluations, %llu pixels resolved, %llu list ends swept; lists of "
                "%d intervals (%d bits per pixel), longest demand %llu ends; %llu pixels overflowed (%llu intervals "
                "dropped)",
                (unsigned long long)objects, (unsigned long long)leaf_pixels, (unsigned long long)resolved,
                (unsigned long long)interval_ends, cfg.csg_list_depth, csgListBitsPerPixel(cfg),
                (unsigned long long)max_list_ends, (unsigned long long)overflowed_pixels,
                (unsigned long long)dropped_intervals);
  std::string s = buf;
  if (cfg.csg_tile_pruning)
    s += "; tile pruning: " + std::to_string(leaves_tested) + " leaf box tests, " + std::to_string(leaves_pruned) +
         " leaves and " + std::to_string(products_pruned) + " products pruned, " + std::to_string(jobs_pruned) +
         " tile jobs empty";
  if (cycles) s += "; CSG pass " + std::to_string(cycles) + " cycles (simulated)";
  return s;
}

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
  j["culled_at_host"] = s.culled_at_host;
  j["facet_primitives"] = s.facet_primitives;
  j["pixels"] = {{"tested", s.pixels.tested},           {"covered", s.pixels.covered},
                 {"caps", s.pixels.caps},               {"clipped", s.pixels.clipped},
                 {"depth_rejected", s.pixels.depth_rejected}, {"written", s.pixels.written},
                 {"clip_passes", s.pixels.clip_passes}, {"distinct_written", s.distinct_written}};
  if (s.csg.objects)
    j["csg"] = {{"objects", s.csg.objects},         {"leaf_pixels", s.csg.leaf_pixels},
                {"interval_ends", s.csg.interval_ends}, {"max_list_ends", s.csg.max_list_ends},
                {"resolved_pixels", s.csg.resolved}, {"overflowed_pixels", s.csg.overflowed_pixels},
                {"dropped_intervals", s.csg.dropped_intervals}, {"cycles", s.csg.cycles},
                {"tile_pruning", s.configuration.csg_tile_pruning},
                {"leaves_tested", s.csg.leaves_tested}, {"leaves_pruned", s.csg.leaves_pruned},
                {"products_pruned", s.csg.products_pruned}, {"jobs_pruned", s.csg.jobs_pruned},
                {"list_depth_intervals", s.configuration.csg_list_depth},
                {"list_bits_per_pixel", csgListBitsPerPixel(s.configuration)}};
  j["overdraw"] = s.overdraw();
  j["overflows"] = {{"total", s.overflow.total()},
                    {"setup", s.overflow.setup.events},
                    {"interpolator", s.overflow.interpolator.events},
                    {"sqrt", s.overflow.sqrt.events},
                    {"depth", s.overflow.depth.events},
                    {"clip", s.overflow.clip.events},
                    {"shading", s.overflow.shading.events},
                    {"depth_clamps", s.overflow.depth_clamps}};
  {
    // Precision lost by the quantised constants, per counter (fixed_point.h quantize(); the
    // setup unit quantises every datapath's constants, so they count under "setup").
    nlohmann::ordered_json p;
    const std::pair<const char*, const OverflowCounter*> d[] = {
        {"setup", &s.overflow.setup}, {"interpolator", &s.overflow.interpolator}, {"sqrt", &s.overflow.sqrt},
        {"depth", &s.overflow.depth}, {"clip", &s.overflow.clip},           {"shading", &s.overflow.shading}};
    for (const auto& [name, c] : d) p[name] = {{"zeroed", c->zeroed}, {"coarse", c->coarse}};
    j["precision_loss"] = p;
  }
  // Visible depths the datapath returned below the primitive's depth floor (0 where the
  // floor's margin holds: then the floor changed no pixel; PrimitiveSetup::zFloor).
  j["depth_floor_clamps"] = s.overflow.depth_floor_clamps;
  if (s.hiz.enabled)
    j["hierarchical_z"] = {{"tile_size", s.configuration.hiz_tile_size},
                           {"depth_bits", HierarchicalZMemory::depthBits(s.configuration)},
                           {"blocks_tested", s.hiz.blocks_tested},
                           {"blocks_rejected", s.hiz.blocks_rejected},
                           {"pixels_rejected", s.hiz.pixels_rejected},
                           {"primitives_tested", s.hiz.primitives_tested},
                           {"primitives_rejected", s.hiz.primitives_rejected},
                           {"issue_cycles_saved", s.hiz.issue_cycles_saved}};
  j["cycles"] = s.cycles;
  j["fast_forwarded_cycles"] = s.fast_forwarded;
  if (!s.simulator_clock.empty()) j["simulator_clock"] = s.simulator_clock;
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
  if (!s.reused.empty()) j["reused"] = s.reused;
  nlohmann::ordered_json units = nlohmann::ordered_json::array();
  for (const auto& u : s.units)
    units.push_back({{"name", u.name}, {"busy", u.busy}, {"stall", u.stall}, {"idle", u.idle}, {"items", u.items}});
  j["units"] = units;
  nlohmann::ordered_json cost = nlohmann::ordered_json::array();
  for (const UnitCost& u : s.cost.units)
    cost.push_back({{"name", u.unit}, {"copies", u.copies}, {"ge_each", u.ge_each}, {"rom_bits", u.rom_bits}});
  j["cost"] = {{"total_ge", s.cost.totalGe()}, {"zbuffer_bits_per_pixel", s.cost.zbufferBitsPerPixel}, {"units", cost}};
  nlohmann::ordered_json csgCost = nlohmann::ordered_json::array();
  for (const UnitCost& u : s.cost.csgUnits)
    csgCost.push_back({{"name", u.unit}, {"copies", u.copies}, {"ge_each", u.ge_each}});
  j["cost"]["csg_option"] = {{"total_ge", s.cost.csgGe()},
                             {"list_bits_per_pixel", s.cost.csgListBitsPerPixel},
                             {"list_memory_bits", s.cost.csgListBits},
                             {"tree_state_bits", s.cost.csgTreeStateBits},
                             {"prune_flag_bits", s.cost.csgPruneFlagBits},
                             {"units", csgCost}};
  if (s.cost.hizBitsPerTile > 0) {
    const double tiles = std::ceil(double(s.width) / s.configuration.hiz_tile_size) *
                         std::ceil(double(s.height) / s.configuration.hiz_tile_size);
    j["cost"]["hierarchical_z"] = {{"ge", s.cost.hizGe},
                                   {"tile_memory_bits_per_tile", s.cost.hizBitsPerTile},
                                   {"tile_memory_bits", tiles * s.cost.hizBitsPerTile},
                                   {"zbuffer_layer_bits_per_pixel", 1}};
  }
  if (s.has_needs) {
    nlohmann::ordered_json needed = nlohmann::ordered_json::array();
    for (const UnitCost& u : s.cost_needed.units)
      needed.push_back({{"name", u.unit}, {"copies", u.copies}, {"ge_each", u.ge_each}, {"rom_bits", u.rom_bits}});
    j["cost_needed"] = {{"total_ge", s.cost_needed.totalGe()},
                        {"solids", s.needs.solids},
                        {"facets", s.needs.facets},
                        {"max_planes", s.needs.max_planes},
                        {"units", needed}};
  }
  j["configuration"] = nlohmann::ordered_json::parse(hwConfigToJson(s.configuration));
  if (s.has_accuracy) {
    nlohmann::ordered_json a;
    for (const auto& [k, v] : s.accuracy.fields()) a[k] = jsonNumber(v);
    j["accuracy"] = a;
  }
  return j;
}

}  // namespace

std::string HwStats::toJson() const { return toJ(*this).dump(2) + "\n"; }

std::string HwStats::countsJson() const {
  nlohmann::ordered_json j = toJ(*this);
  for (const char* k : {"host_seconds", "host_cycles_per_second", "slowdown", "loop_seconds", "loop_cycles_per_second",
                        "trace_seconds", "threads", "simulator_clock", "fast_forwarded_cycles", "reused"})
    j.erase(k);
  return j.dump(2) + "\n";
}

std::string HwStats::toCsv() const { return jsonToCsvRow(toJ(*this)); }

void HwStats::write(const std::string& path) const { writeStatsFiles(path, toJ(*this)); }

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
  std::snprintf(buf, sizeof buf, "primitives: %llu, %llu culled at the host (screen box misses the screen or the depth range)",
                (unsigned long long)primitives, (unsigned long long)culled_at_host);
  out.push_back(buf);
  std::snprintf(buf, sizeof buf,
                "precision loss of the quantised setup constants: %llu non-zero values quantised to zero, %llu left "
                "with fewer than 8 significant bits",
                (unsigned long long)overflow.setup.zeroed, (unsigned long long)overflow.setup.coarse);
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
  if (csg.objects) {
    out.push_back(csg.line(configuration));
    std::string c = "CSG option (cost model, not in the total below): " +
                    std::to_string(int(std::lround(this->cost.csgGe() / 1e3))) + " kGE =";
    for (std::size_t i = 0; i < this->cost.csgUnits.size(); ++i) {
      const UnitCost& u = this->cost.csgUnits[i];
      std::snprintf(buf, sizeof buf, "%s %s %d x %.1f", i ? " +" : "", u.unit.c_str(), u.copies, u.ge_each / 1e3);
      c += buf;
    }
    std::snprintf(buf, sizeof buf, " kGE; list memory %.0f bits (%.0f per pixel, %d tile buffers), tree state %.0f bits",
                  this->cost.csgListBits, this->cost.csgListBitsPerPixel, kCsgListBuffers, this->cost.csgTreeStateBits);
    c += buf;
    if (this->cost.csgPruneFlagBits > 0) {
      std::snprintf(buf, sizeof buf, ", pruning flags %.0f bits", this->cost.csgPruneFlagBits);
      c += buf;
    }
    out.push_back(c);
  }
  out.push_back(cost + " kGE; Z-buffer memory off-chip, " + std::to_string(int(this->cost.zbufferBitsPerPixel)) +
                " bits per pixel");
  if (hiz.enabled) {
    out.push_back(hiz.line(configuration.hiz_tile_size));
    const double tiles = std::ceil(double(width) / configuration.hiz_tile_size) *
                         std::ceil(double(height) / configuration.hiz_tile_size);
    std::snprintf(buf, sizeof buf,
                  "hierarchical Z unit (in the total above): %.1f kGE, tile memory %.0f bits on chip at %dx%d (%d per "
                  "tile), 1 bit per pixel in the Z-buffer record",
                  this->cost.hizGe / 1e3, tiles * this->cost.hizBitsPerTile, width, height, this->cost.hizBitsPerTile);
    out.push_back(buf);
  }
  if (overflow.depth_floor_clamps)
    out.push_back("depth floor: " + std::to_string(overflow.depth_floor_clamps) +
                  " visible depths were below their primitive's floor and raised to it");
  if (has_needs) {
    std::snprintf(buf, sizeof buf, "silicon the scene needs (%s): %.0f kGE of the %.0f kGE above (pixel pipeline %.1f kGE each)",
                  needs.describe().c_str(), cost_needed.totalGe() / 1e3, this->cost.totalGe() / 1e3,
                  [&] {
                    for (const UnitCost& u : cost_needed.units)
                      if (u.unit == "pixel_pipeline") return u.ge_each / 1e3;
                    return 0.0;
                  }());
    out.push_back(buf);
  }
  return out;
}

}  // namespace qacc
