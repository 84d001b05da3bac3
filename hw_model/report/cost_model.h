// CostModel: silicon cost of a configuration in gate equivalents (GE, one 2-input NAND),
// per unit, as a documented function of the configured widths (design §3.2: the cost
// model turns accuracy into silicon cost). The building blocks are the usual figures of
// a 1990s standard-cell library (assumptions, docs/HW_MODEL.md "Cost model"):
//   register bit (D flip-flop)            6 GE
//   adder / comparator bit (carry-select) 10 GE
//   multiplier a x b (array/Wallace)       6 GE per partial-product bit + final adder (a+b)
//   barrel shifter w bits                  2 GE per bit per stage, ceil(log2 w) stages
//   ROM bit                                0.3 GE
//   2:1 multiplexer bit                    2 GE
//   digit recurrence (sqrt, divide), pipelined, one stage per step: (radix - 1) adders of
//   the step's width and the stage's registers (partial remainder + partial result)
//   floating multiply-add (setup, IEEE single) = 24x24 multiplier + 3 adders and a
//   shifter of 48 bits.
// The Z-buffer memory itself is off-chip (counted in bits, not GE).
// The CSG option (interval lists, docs/CSG.md) is priced apart from the base machine
// (`csgUnits`, `csgGe()`), so that the cost of a board without it stays comparable: its
// list memory (kCsgListBuffers tile buffers of 32x32 pixel lists) and the tree state of
// its sweepers and the flags of its box tester (tile pruning) are SRAM, counted in bits;
// its logic in GE.
#pragma once
#include <string>
#include <vector>

#include "hw_model/config/hw_config.h"

namespace qacc {

struct UnitCost {
  std::string unit;
  int copies = 1;        // instances (pipelines, shading units)
  double ge_each = 0;    // gate equivalents of one instance
  double rom_bits = 0;   // of which ROM, in bits (already priced into ge_each)
  std::string basis;     // what was counted
  double total() const { return ge_each * copies; }
};

struct SceneNeeds;

struct CostModel {
  std::vector<UnitCost> units;
  double totalGe() const;
  double zbufferBitsPerPixel = 0;  // off-chip memory per pixel
  // The CSG option.
  std::vector<UnitCost> csgUnits;
  double csgGe() const;
  double csgListBitsPerPixel = 0;  // one pixel's bounded interval list
  double csgListBits = 0;          // the list memory: tile buffers x 32x32 pixels x bits per pixel
  double csgTreeStateBits = 0;     // the sweepers' per-node inside counters
  double csgPruneFlagBits = 0;     // tile pruning: two flags per node, two buffers (0 when off)
  // The hierarchical Z unit (HwConfig::hierarchical_z; a unit of `units`, so in the total,
  // when enabled): its logic, and its tile memory in bits per tile (on chip, SRAM; 0 when
  // disabled) beside one layer bit per pixel in the Z-buffer record.
  double hizGe = 0;
  int hizBitsPerTile = 0;
  // The full configuration, or with `needs` the part of it a scene uses (scene_needs.h): no
  // cap logic without solids, min(K, the scene's largest plane count) clip evaluators, no
  // facet depth interpolator without facets.
  static CostModel of(const HwConfig& cfg, const SceneNeeds* needs = nullptr);
  // Building blocks (GE).
  static double reg(double bits) { return 6.0 * bits; }
  static double adder(double bits) { return 10.0 * bits; }
  static double multiplier(double a, double b) { return 6.0 * a * b + adder(a + b); }
  static double shifter(double bits);
  static double rom(double bits) { return 0.3 * bits; }
  static double mux(double bits) { return 2.0 * bits; }
  static double digitRecurrence(int resultBits, int stepWidth, int radix);
  static double floatMad() { return multiplier(24, 24) + 3 * adder(48) + shifter(48); }
};

}  // namespace qacc
