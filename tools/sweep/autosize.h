// autosize: the cheapest accelerator configuration (cost model) that meets an accuracy
// target on given scenes, by a search over the datapath widths ("size the hardware to the
// scene", `qacc autosize`, docs/SWEEP.md). The search:
//  1. candidates: for each key, its values from the base configuration's down in steps of
//     `step` bits to the key's minimum (or the explicit list given for it);
//  2. bounds: for each key alone, the other keys at the base, the candidates are tried from
//     the base downwards until one fails the target (or the configuration is refused because
//     another key at its base value needs this width); the narrowest passing value bounds the
//     key, since narrowing any other key can only add error (the monotonicity assumption,
//     checked by the widths sweep);
//  3. the grid of the remaining candidates is ordered by gate count (then by the sum of the
//     widths, then lexicographically), and walked: a configuration refused at load or
//     narrower in every key than one that failed is skipped (monotonicity again), the others
//     are rendered; the first that meets the target on every scene is the answer.
// Under the monotonicity assumption the answer is the exact optimum of the candidate grid;
// the test compares it with an exhaustive sweep of a small grid.
#pragma once
#include <map>
#include <string>
#include <vector>

#include <nlohmann/json.hpp>

#include "hw_model/config/hw_config.h"
#include "tools/sweep/accuracy_target.h"
#include "tools/sweep/sweep_evaluator.h"

namespace qacc {

struct AutosizeOptions {
  std::vector<std::string> scenes;
  AccuracyTarget target;
  HwConfig base;
  std::vector<std::string> keys;                // width keys searched (default: every width key)
  int step = 2;                                 // bits between candidates
  std::map<std::string, std::vector<int>> values;  // explicit candidates of a key
  nlohmann::ordered_json knobs = nlohmann::ordered_json::object();  // scene.* (e.g. scene.size)
  std::size_t max_grid = 2000000;               // refuse larger candidate grids
  bool verbose = false;                         // print each evaluation
};

struct AutosizeResult {
  bool found = false;
  HwConfig best;
  double gates_kge = 0, base_gates_kge = 0;
  double worst_wrong_percent = 0;
  double worst_psnr_db = 0;         // the answer's lowest PSNR over the scenes (inf: identical; NaN: not measured)
  std::size_t evaluations = 0;      // configurations rendered (on every scene)
  std::size_t grid = 0;             // candidate configurations after the bounds
  std::map<std::string, int> bound; // narrowest passing value of each key alone
};

AutosizeResult autosize(const AutosizeOptions& o, SweepEvaluator& ev);

}  // namespace qacc
