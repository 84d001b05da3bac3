#include "tools/sweep/sweep_runner.h"

#include <filesystem>

#include "tools/sweep/progress_meter.h"

namespace qacc {

nlohmann::ordered_json pointColumns(std::size_t item, const SweepPoint& p) {
  nlohmann::ordered_json row;
  row["item"] = item;
  row["point"] = p.index;
  row["label"] = p.label;
  row["config"] = p.config.name;
  for (const std::string& k : hwConfigKeys())
    if (k != "name") row["config." + k] = hwConfigValue(p.config, k);
  return row;
}

SweepResults runSweep(const SweepSpec& spec, const Shard& shard, SweepEvaluator& evaluator) {
  const std::vector<SweepPoint> points = sweepPoints(spec);
  SweepResults r;
  r.spec = spec.json;
  r.spec_file = spec.file;
  r.spec_hash = spec.hash;
  r.target = spec.target;
  r.points = points.size();
  r.scenes = spec.scenes.size();
  r.shard = shard.count > 1 ? shard.text() : "";
  const std::size_t total = points.size() * spec.scenes.size();
  std::size_t mine = 0;
  for (std::size_t i = 0; i < total; ++i) mine += shard.takes(i);
  ProgressMeter progress(mine, "sweep " + spec.name + (shard.count > 1 ? " shard " + shard.text() : "") + ":");
  for (std::size_t item = 0; item < total; ++item) {
    if (!shard.takes(item)) continue;
    const SweepPoint& p = points[item / spec.scenes.size()];
    const std::string& scene = spec.scenes[item % spec.scenes.size()];
    nlohmann::ordered_json row = pointColumns(item, p);
    if (!p.refused.empty()) {
      row["scene"] = std::filesystem::path(scene).stem().string();
      SweepEvaluator::knobColumns(p.knobs, row);
      row["status"] = "refused";
      row["note"] = p.refused;
    } else {
      const nlohmann::ordered_json m = evaluator.evaluate(p.config, p.knobs, scene, "item" + std::to_string(item));
      for (auto it = m.begin(); it != m.end(); ++it) row[it.key()] = it.value();
    }
    r.rows.push_back(std::move(row));
    progress.step(p.label);
  }
  progress.finish();
  return r;
}

}  // namespace qacc
