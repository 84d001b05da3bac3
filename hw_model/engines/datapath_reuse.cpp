#include "hw_model/engines/datapath_reuse.h"

namespace qacc {

std::size_t DatapathReuse::Entry::bytes() const {
  std::size_t n = winners.size() * sizeof(ZEntry) + frame.color.data.size() +
                  frame.depth.size() * sizeof(double) +
                  (frame.object.size() + frame.primitive.size()) * sizeof(std::int32_t) +
                  trace.pixels.size() * sizeof(TracedPixel) +
                  (trace.first.size() + trace.passes.size()) * sizeof(std::size_t);
  for (const auto& rows : trace.rows) n += rows.size() * sizeof(RowSpans);
  for (const PrimitiveSetup& s : setup.setups)
    n += sizeof(PrimitiveSetup) + s.planes.size() * sizeof(PlaneSetup) + s.pointLights.size() * sizeof(VectorSetup);
  return n;
}

std::string DatapathReuse::scene(int width, int height) const {
  return std::to_string(width) + "x" + std::to_string(height) + "\n" + content_;
}

DatapathReuse::Entry* DatapathReuse::find(int width, int height, const HwConfig& cfg) {
  const auto it = entries_.find(slot_);
  if (it == entries_.end()) return nullptr;
  if (it->second->scene == scene(width, height) && it->second->datapath == hwDatapathKey(cfg)) return it->second.get();
  entries_.erase(it);
  return nullptr;
}

void DatapathReuse::keep(int width, int height, const HwConfig& cfg, Entry&& e) {
  entries_.erase(slot_);
  e.scene = scene(width, height);
  e.datapath = hwDatapathKey(cfg);
  std::size_t kept = 0;
  for (const auto& [slot, entry] : entries_) kept += entry->bytes();
  if (kept + e.bytes() <= maxBytes_) entries_[slot_] = std::make_unique<Entry>(std::move(e));
}

}  // namespace qacc
