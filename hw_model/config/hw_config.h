// HwConfig: every parameter of the emulated accelerator (docs/HW_MODEL.md gives each
// default and the argument for it), flat as in the JSON file; each timed unit derives its
// own parameter section from it (`Params::from`, timing/), with its latency formula. Loaded from one JSON file (`--config`); a key that is
// absent keeps its default, an unknown key or a value out of range is refused.
#pragma once
#include <cstddef>
#include <string>
#include <vector>

#include <nlohmann/json_fwd.hpp>

#include "hw_model/datapath/fixed_point.h"

namespace qacc {

enum class DepthVariant { Stable, Reciprocal };
// How the shading unit normalises vectors: seed ROM + one Newton step (datapath/reciprocal_sqrt.h), or
// a digit-recurrence square root followed by a divider.
enum class Normalizer { Newton, Recurrence };

struct HwConfig {
  std::string name = "default";
  // Clock and host interface.
  double clock_mhz = 50.0;     // modeled core clock
  int bus_width_bits = 32;     // host bus data width
  int bus_cycles_per_word = 1; // core cycles per bus transfer
  int descriptor_word_bits = 32;  // one coefficient / plane / attribute word (IEEE single)
  int host_fifo_depth = 4;     // primitive descriptors buffered after the host interface
  // Setup.
  int setup_mad_units = 4;     // multiply-add units of the setup processor
  int setup_fifo_depth = 2;    // set-up primitives waiting for traversal
  // Pixel pipelines.
  int pipelines = 2;           // P, screen-interleaved pixel pipelines
  int pixel_fifo_depth = 8;    // traversal -> pipeline, pipeline -> Z, Z -> shading FIFOs
  int clip_evaluators = 4;     // K linear evaluators; more planes cost extra passes
  // Datapaths (bits).
  int value_bits = 32;         // a, b, c and sqrt(Δ) (block floating, per primitive)
  int delta_bits = 64;         // Δ = b² − ac (block floating, per primitive); sqrt input
  int interp_frac_bits = 24;   // extra fraction bits of interpolator coefficients
  int interp_acc_bits = 100;   // interpolator accumulator width
  int depth_frac_bits = 28;    // internal window depth fraction bits
  int depth_bits = 32;         // internal window depth width (sign + integer + fraction)
  int clip_bits = 32;          // clip-plane values (block floating, per plane)
  int recip_bits = 32;         // 1/a mantissa (reciprocal depth variant)
  int zbuffer_bits = 24;       // stored depth
  int normal_bits = 16;        // normal / view / light vector mantissas after normalisation
  int unit_frac_bits = 14;     // unit vectors and dot products (1.14)
  int color_frac_bits = 12;    // linear colour (0.12), input of the sRGB table
  Rounding rounding = Rounding::Nearest;
  OverflowMode overflow = OverflowMode::Saturate;
  // Arithmetic units.
  int sqrt_radix = 4;          // digit-recurrence radix (2 or 4): bits per step = log2(radix)
  int divider_radix = 4;       // digit-recurrence divider radix (2 or 4)
  DepthVariant depth_variant = DepthVariant::Stable;
  int shading_cycles_per_pixel = 1;  // shading initiation interval
  int shading_latency = 12;
  Normalizer shading_normalizer = Normalizer::Newton;
  // Z-buffer memory.
  int zbuffer_banks = 4;
  int zbuffer_read_latency = 2;  // cycles from request to data
  int zbuffer_bank_busy = 2;     // cycles a bank is occupied by one read-modify-write
  // CSG interval lists (datapath/csg_interval_list.h, docs/CSG.md).
  int csg_list_depth = 32;       // intervals per pixel list (the shipped scenes need up to 32)
  int csg_leaf_bits = 11;        // leaf index of a list entry: up to 2^11 leaves per csg object
  int csg_tag_bits = 4;          // end tag: surface, near/far, or one of 2^4 - 2 clip planes
  // Per tile, the tree pruned by its leaves' screen boxes (modeling/csg/csg_tree_pruning.h):
  // only the leaves still needed run; the box tests cost cycles in the CSG issue unit.
  bool csg_tile_pruning = true;
  // Hierarchical Z (coarse occlusion culling, datapath/hierarchical_z_memory.h, off as on the
  // boards of the 1990s): per screen tile of hiz_tile_size² pixels a conservative maximum
  // stored depth, held in hiz_depth_bits (at most zbuffer_bits); a block of a span whose
  // primitive's depth floor is not nearer than it is rejected before the pixel pipelines.
  bool hierarchical_z = false;
  int hiz_tile_size = 8;         // 4, 8, 16 or 32 (a divisor of the 32x32 traversal tiles)
  int hiz_depth_bits = 12;       // the tile maxima, rounded up (conservative)
};

// The configuration file format: strict JSON (modeling/scene/strict_json.h: syntax errors
// with line and column, duplicate keys refused), "format" required and equal to
// kHwConfigFormat, "comment" a string, every other key a parameter; read with a size bound.
constexpr const char* kHwConfigFormat = "qacc-hw-config/1";
constexpr std::size_t kMaxHwConfigBytes = std::size_t(1) << 20;
// The largest unit_frac_bits accepted: the specular table (2^unit_frac_bits + 1 entries per
// material) is built in full before the first pixel.
constexpr int kMaxUnitFracBits = 20;
// A configuration without a "name" is named after its file (stem of `file`).
HwConfig loadHwConfig(const std::string& path);
HwConfig parseHwConfig(const std::string& text, const std::string& file);
// Every configuration key (sorted), and whether a key is a datapath width (the keys
// `qacc autosize` narrows and the cost model prices by width).
std::vector<std::string> hwConfigKeys();
bool isHwWidthKey(const std::string& key);
// Whether a key only says when things happen (clock, bus, FIFO depths, unit counts,
// latencies, radices, the hierarchical Z unit's tiles): the setup arithmetic, the pixel
// datapath's results and the shading of the winners — every bit of the image — do not depend
// on it. The timed units and the cost model read it; besides them, only counts of work do
// (clip_evaluators: a primitive's passes through the clip unit, PixelDatapath::clipPassesOf;
// clip_evaluators and csg_tile_pruning: the CSG pass's jobs, built at every render). Every
// other key, and any key added later until it is listed here, counts as datapath.
bool isHwTimingKey(const std::string& key);
// The configuration's datapath keys and values ("key=value" lines, every key that is neither
// a timing key nor the name): two configurations with the same text compute the same bits.
std::string hwDatapathKey(const HwConfig& c);
// Sets one key from a JSON value; `where` prefixes the message ("FILE: /json/path").
// Throws std::invalid_argument for an unknown key or a value out of range.
void setHwConfigKey(HwConfig& c, const std::string& key, const nlohmann::json& value, const std::string& where);
// The JSON value of one key.
nlohmann::json hwConfigValue(const HwConfig& c, const std::string& key);
// The checks that involve several keys (a width too narrow for another, with the reason);
// throws std::invalid_argument "where: /key: problem".
void checkHwConfig(const HwConfig& c, const std::string& where);
// JSON text of a configuration (every key, so a saved file documents itself).
std::string hwConfigToJson(const HwConfig& c);

}  // namespace qacc
