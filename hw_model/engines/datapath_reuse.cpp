#include "hw_model/engines/datapath_reuse.h"

#include <set>
#include <stdexcept>

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
  // The lighting's ROMs: the sRGB table and each specular table once (materials share them).
  n += setup.lighting.srgb.size();
  std::set<const std::vector<std::int32_t>*> tables;
  for (const LightingSetup::MaterialQ& m : setup.lighting.materials)
    if (m.specular && tables.insert(m.specular.get()).second) n += m.specular->size() * sizeof(std::int32_t);
  return n;
}

std::string DatapathReuse::scene(int width, int height) const {
  if (!named_) throw std::logic_error("DatapathReuse: a render before setScene named its scene");
  return std::to_string(width) + "x" + std::to_string(height) + "\n" + content_;
}

DatapathReuse::Entry* DatapathReuse::find(int width, int height, const HwConfig& cfg) {
  const std::string wanted = scene(width, height);
  const auto it = entries_.find(slot_);
  if (it == entries_.end()) return nullptr;
  if (it->second->scene == wanted && it->second->datapath == hwDatapathKey(cfg)) return it->second.get();
  entries_.erase(it);
  return nullptr;
}

std::size_t DatapathReuse::otherSlotsBytes() const {
  std::size_t kept = 0;
  for (const auto& [slot, entry] : entries_)
    if (slot != slot_) kept += entry->bytes();
  return kept;
}

bool DatapathReuse::mayKeep(int width, int height) const {
  const std::size_t pixels = std::size_t(width) * std::size_t(height);
  return otherSlotsBytes() + pixels * (sizeof(ZEntry) + 3 + sizeof(double) + 2 * sizeof(std::int32_t)) <= maxBytes_;
}

void DatapathReuse::keep(int width, int height, const HwConfig& cfg, Entry&& e) {
  entries_.erase(slot_);
  e.scene = scene(width, height);
  e.datapath = hwDatapathKey(cfg);
  if (otherSlotsBytes() + e.bytes() <= maxBytes_) entries_[slot_] = std::make_unique<Entry>(std::move(e));
}

}  // namespace qacc
