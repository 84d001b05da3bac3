// The results of a sweep (or of one shard of it): the spec, one row per work item (point,
// scene) in item order with every configuration key as a column (config.KEY), the Pareto
// fronts and the answer to the spec's target. Written as DIR/results.json (everything),
// DIR/results.csv (the rows) and DIR/fronts.csv; read back for `qacc sweep --merge`.
//
// Fronts (pareto_front.h), error = wrong_percent, for each scene and for "all" scenes
// (a point's error is its worst scene's, its pinholes and cycles the sums; a point is on
// the "all" fronts only if every scene ran): error against gate count (gates_kge) and
// error against cycles. Answer: the cheapest point (gate count, then cycles, then index)
// whose every scene meets the target.
#pragma once
#include <string>
#include <vector>

#include <nlohmann/json.hpp>

namespace qacc {

struct SweepResults {
  nlohmann::ordered_json spec;  // as read
  std::string spec_file, spec_hash, target;
  std::size_t points = 0, scenes = 0;  // work items = points x scenes
  std::string shard;                   // "I/N" for one shard, "" for a complete sweep
  std::vector<nlohmann::ordered_json> rows;
};

nlohmann::ordered_json sweepFronts(const SweepResults& r);
// An answer's lowest PSNR over its scenes as `qacc sweep` and `qacc autosize` print it:
// "lowest PSNR 46.8 dB", "every image identical to the reference" (inf), or "PSNR not
// measured" (NaN: a scene without it). A target on wrong pixels alone says nothing of colour.
std::string lowestPsnrText(double psnr);
// `lowest` (a lowest PSNR so far: inf before the first row) with the row's psnr_db folded in:
// the lower of the two, NaN once a row lacks it (then the lowest is unknown).
double foldLowestPsnr(double lowest, const nlohmann::ordered_json& row);
// Columns that depend on the host (timing, cache state); everything else is a function of
// the spec alone, so a merged sweep equals an unsharded one on the other columns.
bool isHostColumn(const std::string& column);
void writeSweepResults(const std::string& dir, const SweepResults& r);
SweepResults readSweepResults(const std::string& dir);
// Shards of one spec (same hash), each item exactly once; the result is complete.
SweepResults mergeSweepResults(const std::vector<SweepResults>& parts, const std::vector<std::string>& names);

}  // namespace qacc
