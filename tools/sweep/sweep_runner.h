// runSweep: the items of a sweep (all, or one shard's) in item order, each measured by the
// SweepEvaluator; a refused configuration gives a row with status "refused" and the
// reason, never a crash. Every row starts with item, point, label, the configuration name
// and every configuration key (config.KEY).
#pragma once
#include "tools/sweep/sweep_evaluator.h"
#include "tools/sweep/sweep_points.h"
#include "tools/sweep/sweep_results.h"
#include "tools/sweep/sweep_spec.h"

namespace qacc {

SweepResults runSweep(const SweepSpec& spec, const Shard& shard, SweepEvaluator& evaluator);
// The leading columns of a row: item, point, label, config name, config.KEY for every key.
nlohmann::ordered_json pointColumns(std::size_t item, const SweepPoint& p);

}  // namespace qacc
