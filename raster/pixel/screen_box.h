// ScreenBox: a half-open pixel rectangle [x0, x1) x [y0, y1).
#pragma once
#include <algorithm>

namespace qacc {

struct ScreenBox {
  int x0 = 0, y0 = 0, x1 = 0, y1 = 0;
  bool empty() const { return x1 <= x0 || y1 <= y0; }
  ScreenBox intersect(const ScreenBox& o) const {
    return {std::max(x0, o.x0), std::max(y0, o.y0), std::min(x1, o.x1), std::min(y1, o.y1)};
  }
  long long area() const { return empty() ? 0 : (long long)(x1 - x0) * (y1 - y0); }
};

}  // namespace qacc
