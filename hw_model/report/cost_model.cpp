#include "hw_model/report/cost_model.h"

#include <algorithm>
#include <cmath>

#include "hw_model/datapath/csg_interval_list.h"
#include "hw_model/datapath/hierarchical_z_memory.h"
#include "hw_model/datapath/reciprocal_sqrt.h"
#include "hw_model/report/scene_needs.h"
#include "hw_model/timing/hierarchical_z_unit.h"
#include "hw_model/timing/pixel_pipeline_unit.h"
#include "raster/pixel/tile_binner.h"

namespace qacc {

double CostModel::shifter(double bits) { return 2.0 * bits * std::ceil(std::log2(std::max(2.0, bits))); }

double CostModel::digitRecurrence(int resultBits, int stepWidth, int radix) {
  const int perStep = radix == 4 ? 2 : 1;
  const int steps = (resultBits + perStep - 1) / perStep;
  // Each stage: (radix - 1) trial adders, registers for the partial remainder and result.
  return steps * ((radix - 1) * adder(stepWidth) + reg(stepWidth + resultBits));
}

double CostModel::csgGe() const {
  double t = 0;
  for (const UnitCost& u : csgUnits) t += u.total();
  return t;
}

double CostModel::totalGe() const {
  double t = 0;
  for (const UnitCost& u : units) t += u.total();
  return t;
}

CostModel CostModel::of(const HwConfig& c, const SceneNeeds* needs) {
  CostModel m;
  const int P = c.pipelines, K = needs ? std::min(c.clip_evaluators, needs->max_planes) : c.clip_evaluators;
  const bool caps = !needs || needs->solids, facets = !needs || needs->facets;
  const int acc = c.interp_acc_bits;
  // Interpolators (forward differences): a quadratic one keeps value, first and second
  // differences and a row-start copy (4 registers, 3 adders); a linear one keeps value,
  // row start and two steps (3 registers, 2 adders).
  const double quadInterp = 4 * reg(acc) + 3 * adder(acc);
  const double linInterp = 3 * reg(acc) + 2 * adder(acc);
  const int tokenBits = 12 + 12 + 16 + 16;  // x, y, primitive, issue index
  const int zReqBits = 12 + 12 + 16 + 4 + c.depth_bits;

  // A descriptor with six clip planes (with `needs`: the scene's largest, up to six).
  const int descWords = 10 + 4 * (needs ? std::min(6, needs->max_planes) : 6) + 2;
  m.units.push_back({"host_interface", 1,
                     reg(c.bus_width_bits) + reg(double(descWords) * c.descriptor_word_bits) * (1 + c.host_fifo_depth), 0,
                     "bus register, descriptor assembly buffer and host FIFO (" +
                         std::to_string((descWords - 12) / 4) + "-plane descriptors)"});
  m.units.push_back({"setup", 1,
                     c.setup_mad_units * floatMad() + reg(double(descWords) * 32 * 2) +
                         reg(40.0 * acc) * c.setup_fifo_depth,
                     0, "floating multiply-add units, operand registers, setup FIFO of interpolator seeds"});
  m.units.push_back({"traversal", 1, 2 * floatMad() + adder(32) + reg(4 * 16) + reg(double(tokenBits)) * P,
                     0, "span solver (conic roots per row, floating point), counters, pixel issue"});

  // One pixel pipeline.
  const int sqrtIn = c.delta_bits + 1, sqrtOut = (sqrtIn + 1) / 2;
  double depthGe;
  std::string depthBasis;
  if (c.depth_variant == DepthVariant::Stable) {
    depthGe = adder(c.value_bits + 1) + 2 * digitRecurrence(c.depth_bits, c.depth_bits + 2, c.divider_radix);
    depthBasis = "q = -(b + sign(b) s) adder, two dividers (q/a, c/q)";
  } else {
    depthGe = 2 * adder(c.value_bits + 1) + 2 * multiplier(c.value_bits + 1, c.recip_bits);
    depthBasis = "two adders, two multipliers by 1/a";
  }
  const double clipGe = K * (linInterp + multiplier(c.clip_bits, c.depth_bits) + adder(c.clip_bits + c.depth_bits));
  const double capGe = caps ? K * (linInterp + adder(c.depth_bits)) + 2 * adder(c.depth_bits) : 0.0;
  const double facetGe = facets ? linInterp : 0.0;  // the facet path's depth interpolator
  const double pipeGe = 2 * quadInterp + linInterp + digitRecurrence(sqrtOut, sqrtOut + 2, c.sqrt_radix) + depthGe +
                        clipGe + capGe + facetGe +
                        reg(double(PixelPipelineUnit::Params::from(c).latency) * (tokenBits + c.depth_bits)) +
                        3 * reg(double(c.pixel_fifo_depth) * tokenBits);
  m.units.push_back({"pixel_pipeline", P, pipeGe, 0,
                     "Δ and c quadratic, b linear interpolators; sqrt (" + std::to_string(sqrtIn) + "-bit input, radix " +
                         std::to_string(c.sqrt_radix) + "); depth: " + depthBasis + "; " + std::to_string(K) +
                         " clip evaluators" + (caps ? " and cap depths" : "") +
                         (facets ? "; facet depth interpolator" : "") + "; pipeline and FIFO registers"});

  // Z-buffer controller: one comparator per pipeline, bank state, read pipeline.
  m.units.push_back({"zbuffer", 1,
                     P * (adder(c.zbuffer_bits) + reg(double(c.zbuffer_read_latency) * zReqBits)) +
                         c.zbuffer_banks * (reg(24) + reg(4) + adder(4)) +
                         P * reg(double(c.pixel_fifo_depth) * zReqBits),
                     0, "depth comparators, bank address and busy counters, read latency registers, Z FIFOs"});

  // One shading unit: field evaluation (normal, view), normalisers (N, V, and H for one
  // light per cycle), dot products, colour, specular table and sRGB ROM.
  const int nb = c.normal_bits, uf = c.unit_frac_bits, cf = c.color_frac_bits, G = 8;
  const double field = 3 * (linInterp + multiplier(nb + 8, c.depth_bits));
  const int Pr = ReciprocalSqrt::kPrecision;
  const double rsqrt =
      c.shading_normalizer == Normalizer::Newton
          ? shifter(2 * nb) + rom(ReciprocalSqrt::romBits()) + multiplier(Pr + 1, Pr + 1) +
                multiplier(2 * Pr + 2, 2 * Pr + 2) + adder(4 * Pr + 4) + multiplier(Pr + 1, 2 * Pr + 2) +
                3 * multiplier(nb, Pr + 1)
          : digitRecurrence(nb + G, nb + G + 2, c.sqrt_radix) + digitRecurrence(uf + 2, uf + G + nb, c.divider_radix) +
                3 * multiplier(nb, uf + 2);
  const double normaliser = 3 * shifter(acc) + 3 * multiplier(nb, nb) + 2 * adder(2 * nb) + rsqrt;
  const double dot3 = 3 * multiplier(uf + 2, uf + 2) + 2 * adder(2 * uf + 4);
  const double colour = 3 * (multiplier(cf + 2, uf + 2) + multiplier(cf + 8, cf + 2) + 2 * adder(cf + 8));
  const double specRom = double((1 << uf) + 1) * (cf + 4), srgbRom = double((1 << cf) + 1) * 8;
  const double rsqrtRom = c.shading_normalizer == Normalizer::Newton ? 3.0 * ReciprocalSqrt::romBits() : 0.0;
  m.units.push_back({"shading", P,
                     2 * field + 3 * normaliser + 3 * dot3 + colour + rom(specRom + srgbRom) +
                         reg(double(c.shading_latency) * (zReqBits + 3 * (uf + 2))),
                     specRom + srgbRom + rsqrtRom,
                     std::string("normal and view fields, 3 normalisers (rsqrt: ") +
                         (c.shading_normalizer == Normalizer::Newton ? "seed ROM + one Newton step"
                                                                     : "digit-recurrence sqrt + divider") +
                         "), 3 dot products, colour multipliers, specular table and sRGB ROM, pipeline registers"});
  m.zbufferBitsPerPixel = c.zbuffer_bits;

  // The hierarchical Z unit (datapath/hierarchical_z_memory.h, timing/hierarchical_z_unit.h):
  // the lookup (tile address adders, the floor register, the comparator of the floor with
  // the tile's bound), per Z port a tile-record update (layer-bit compare, the max comparator,
  // the count incrementer and its "tile full" comparator, the record's multiplexers and its
  // registers for the update latency), and per pixel pipeline the depth floor's comparator and
  // multiplexer after the depth unit.
  if (c.hierarchical_z) {
    const int db = HierarchicalZMemory::depthBits(c), rec = HierarchicalZMemory::bitsPerTile(c);
    const int countBits = rec - 2 * db - 2;
    const double lookup = 2 * adder(16) + reg(c.zbuffer_bits) + adder(db + 1);
    const double update = 2 * adder(db) + 2 * adder(countBits) + mux(rec) +
                          reg(double(rec) * HierarchicalZUnit::Params::from(c).update_latency);
    const double floorClamp = adder(c.depth_bits) + mux(c.depth_bits);
    m.hizGe = lookup + P * (update + floorClamp);
    m.hizBitsPerTile = rec;
    m.units.push_back({"hierarchical_z", 1, m.hizGe, 0,
                       "lookup (tile address, floor comparator), " + std::to_string(P) +
                           " tile-record update ports, " + std::to_string(P) + " depth-floor clamps; tile memory " +
                           std::to_string(rec) + " bits per " + std::to_string(c.hiz_tile_size) + "x" +
                           std::to_string(c.hiz_tile_size) + " tile (SRAM, not in GE)"});
  }

  // The CSG option: per pipeline an insertion port of the list memory and a sweeper.
  const int D = c.csg_list_depth, leafBits = c.csg_leaf_bits;
  const int entryBits = 2 * c.depth_bits + leafBits + 2 * c.csg_tag_bits;
  const int listWord = csgListCountBits(c) + 1 + D * entryBits;
  // Insertion: the pixel's list word is read, the new entry's depth compared with every
  // stored entry's at once, each slot takes its old entry, the new one or its
  // predecessor's (two 2:1 multiplexers per bit), and the word is written back.
  m.csgUnits.push_back({"csg_list_port", P, D * adder(c.depth_bits) + 2 * mux(double(D) * entryBits) + reg(listWord), 0,
                        std::to_string(D) + " depth comparators, " + std::to_string(D) + "-entry insertion network, " +
                            std::to_string(listWord) + "-bit list word register"});
  // Sweep: the entries come in depth order from the list; the exits wait in a sorted
  // buffer of D (a comparator and a register per slot); the event comparator with its
  // tolerance; the walk up the tree (a counter adder and the node address).
  const int nodeBits = leafBits + 1, counterBits = leafBits + 1;
  m.csgUnits.push_back({"csg_sweep", P,
                        D * (adder(c.depth_bits) + reg(c.depth_bits + leafBits + c.csg_tag_bits)) +
                            2 * adder(c.depth_bits) + adder(counterBits) + reg(nodeBits + counterBits) +
                            reg(2.0 * entryBits),
                        0,
                        "exit buffer of " + std::to_string(D) + " (comparators, registers), event comparator, "
                        "tree walk (counter adder, node register)"});
  // Tile pruning (csg_tile_pruning): one box tester in the issue unit, walking the tree's
  // nodes in post order, one per cycle: a leaf's screen box (four coordinates) compared with
  // the tile's edges by four comparators; an inner node's emptiness from its operands' flags
  // (a few gates, not counted); the node counter. The flags (empty, needed) are SRAM, in
  // two buffers: the tester fills the next job's while the current job issues.
  if (c.csg_tile_pruning) {
    const int coordBits = 12;  // screen x or y, as in the pixel tokens
    m.csgUnits.push_back({"csg_box_tester", 1,
                          4 * adder(coordBits) + reg(4 * coordBits) + reg(2 * coordBits) + adder(nodeBits) +
                              reg(nodeBits),
                          0,
                          "4 comparators of " + std::to_string(coordBits) +
                              "-bit screen coordinates (a leaf's box against the tile), box and tile registers, "
                              "node counter"});
    m.csgPruneFlagBits = 2.0 * 2.0 * double(2LL << leafBits);
  }
  m.csgListBitsPerPixel = qacc::csgListBitsPerPixel(c);
  m.csgListBits = double(kCsgListBuffers) * TileBinner::kTileSize * TileBinner::kTileSize * m.csgListBitsPerPixel;
  // Per sweeper: an inside counter per node of a tree of up to 2^csg_leaf_bits leaves.
  m.csgTreeStateBits = double(P) * double(2LL << leafBits) * counterBits;
  return m;
}

}  // namespace qacc
