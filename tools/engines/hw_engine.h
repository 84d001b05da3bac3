// The accelerator engines of `qacc render --engine`: `hw` (functional) and `hw-cycle`
// (cycle-level). Both read --config (default configuration when absent), write --stats
// (JSON + CSV) and print the statistics summary and the accuracy against the reference.
#pragma once
#include <string>
#include <vector>

#include "hw_model/config/hw_config.h"
#include "hw_model/engines/datapath_reuse.h"
#include "hw_model/report/hw_stats.h"
#include "tools/engines/engine.h"

namespace qacc {

std::vector<std::string> hwEngineNames();
// Renders with `engine` if it is an accelerator engine (returns false otherwise).
bool runHwEngine(const std::string& engine, const Scene& scene, const EngineOptions& options, EngineResult& out);
// The same, returning the statistics too (for bench). hw-cycle takes what it can from `reuse`
// and keeps its own there (hw_model/engines/datapath_reuse.h); hw does not use it.
FrameBuffer renderWithHwEngine(const std::string& engine, const Scene& scene, const HwConfig& cfg, int threads,
                               HwStats& stats, DatapathReuse* reuse = nullptr);

}  // namespace qacc
