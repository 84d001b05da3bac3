#include "hw_model/datapath/csg_interval_list.h"

#include <algorithm>

namespace qacc {

bool CsgIntervalList::insert(const CsgListInterval& iv, int depth) {
  const std::size_t pos = std::size_t(
      std::upper_bound(items_.begin(), items_.end(), iv.zin,
                       [](std::int64_t z, const CsgListInterval& e) { return z < e.zin; }) -
      items_.begin());
  if (int(items_.size()) < depth) {
    items_.insert(items_.begin() + std::ptrdiff_t(pos), iv);
    return true;
  }
  overflowed_ = true;
  if (pos == items_.size()) return false;  // not nearer than the farthest kept: dropped
  items_.pop_back();
  items_.insert(items_.begin() + std::ptrdiff_t(pos), iv);
  return false;
}

int csgListCountBits(const HwConfig& cfg) {
  int bits = 0;
  while ((1 << bits) < cfg.csg_list_depth + 1) ++bits;
  return bits;
}

int csgListBitsPerPixel(const HwConfig& cfg) {
  return csgListCountBits(cfg) + 1 + cfg.csg_list_depth * (2 * cfg.depth_bits + cfg.csg_leaf_bits + 2 * cfg.csg_tag_bits);
}

}  // namespace qacc
