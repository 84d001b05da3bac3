#include "modeling/csg/csg_product_pruning.h"

namespace qacc {

CsgProduct pruneProduct(const CsgProduct& product, const std::vector<Eigen::AlignedBox3d>& boxes) {
  bool anyPositive = false;
  Eigen::AlignedBox3d common;  // the positive literals' common box
  for (const CsgLiteral& l : product) {
    if (l.complement) continue;
    const Eigen::AlignedBox3d& b = boxes[std::size_t(l.primitive)];
    common = anyPositive ? common.intersection(b) : b;
    anyPositive = true;
  }
  if (!anyPositive) return product;
  if (common.isEmpty()) return {};
  CsgProduct kept;
  for (const CsgLiteral& l : product)
    if (!l.complement || !common.intersection(boxes[std::size_t(l.primitive)]).isEmpty()) kept.push_back(l);
  return kept;
}

}  // namespace qacc
