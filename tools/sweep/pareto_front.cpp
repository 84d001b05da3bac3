#include "tools/sweep/pareto_front.h"

#include <algorithm>
#include <cmath>
#include <limits>

namespace qacc {

std::vector<std::size_t> paretoFront(const std::vector<std::pair<double, double>>& p) {
  std::vector<std::size_t> order;
  for (std::size_t i = 0; i < p.size(); ++i)
    if (!std::isnan(p[i].first) && !std::isnan(p[i].second)) order.push_back(i);
  std::sort(order.begin(), order.end(), [&](std::size_t a, std::size_t b) {
    return p[a] != p[b] ? p[a] < p[b] : a < b;
  });
  std::vector<std::size_t> front;
  double best = std::numeric_limits<double>::infinity();
  for (std::size_t k = 0; k < order.size(); ++k) {
    const auto& q = p[order[k]];
    // Kept when strictly better in the second measure than everything before it, or equal
    // to the last point kept.
    if (q.second < best || (!front.empty() && q == p[front.back()])) {
      front.push_back(order[k]);
      best = std::min(best, q.second);
    }
  }
  return front;
}

}  // namespace qacc
