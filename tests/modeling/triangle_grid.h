// A square [lo, hi]^2 cut into n x n squares, each split into two triangles along its
// diagonal: the domain triangulation of the simplex-spline height-field tests.
#pragma once

#include <array>
#include <vector>

#include <Eigen/Core>

struct TriangleGrid {
  std::vector<Eigen::Vector2d> v;
  std::vector<std::array<int, 3>> t;
};

inline TriangleGrid triangleGrid(int n, double lo, double hi) {
  TriangleGrid g;
  for (int j = 0; j <= n; ++j)
    for (int i = 0; i <= n; ++i) g.v.emplace_back(lo + (hi - lo) * i / n, lo + (hi - lo) * j / n);
  for (int j = 0; j < n; ++j)
    for (int i = 0; i < n; ++i) {
      const int a = j * (n + 1) + i, b = a + 1, c = a + n + 1, d = c + 1;
      g.t.push_back({a, b, d});
      g.t.push_back({a, d, c});
    }
  return g;
}
