// Pareto front of points to minimise in two measures (error against gate count, error
// against cycles): the points no other point beats in one measure without losing in the
// other. Points with a NaN measure are never on the front; equal points are all kept.
#pragma once
#include <cstddef>
#include <utility>
#include <vector>

namespace qacc {

// Indices of the front, sorted by the first measure (then the second).
std::vector<std::size_t> paretoFront(const std::vector<std::pair<double, double>>& points);

}  // namespace qacc
