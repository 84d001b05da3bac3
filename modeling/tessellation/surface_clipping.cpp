#include "modeling/tessellation/surface_clipping.h"

#include <algorithm>
#include <cmath>

namespace qacc::tess {

bool lexLess(const Vector3d& a, const Vector3d& b) {
  if (a.x() != b.x()) return a.x() < b.x();
  if (a.y() != b.y()) return a.y() < b.y();
  return a.z() < b.z();
}

Polygon clipPolygon(const Polygon& in, const Domain& d, const std::vector<HalfSpace>& planes) {
  Polygon poly = in;
  for (std::size_t k = 0; k < planes.size() && !poly.empty(); ++k) {
    const unsigned bit = k < 32 ? (1u << k) : 0u;
    std::vector<char> kept(poly.size());
    bool all = true, none = true;
    for (std::size_t i = 0; i < poly.size(); ++i) {
      kept[i] = (poly[i].tags & bit) ? 1 : char(planes[k].keeps(planes[k].eval(d.position(poly[i].coord))));
      all = all && kept[i];
      none = none && !kept[i];
    }
    if (all) continue;
    if (none) return {};
    Polygon out;
    for (std::size_t i = 0; i < poly.size(); ++i) {
      const std::size_t j = (i + 1) % poly.size();
      if (kept[i]) out.push_back(poly[i]);
      if (kept[i] != kept[j]) {
        ClipVertex v;
        v.coord = d.cut(poly[i].coord, poly[j].coord, planes[k]);
        v.tags = (poly[i].tags & poly[j].tags) | bit;
        if (!d.linear && (v.tags & ~bit)) {  // a corner: on the surface and on two planes
          for (std::size_t m = 0; m < planes.size() && m < 32; ++m)
            if (m != k && (v.tags & (1u << m))) {
              v.coord = d.corner(v.coord, planes[m], planes[k]);
              break;
            }
        }
        out.push_back(v);
      }
    }
    poly.swap(out);
  }
  return poly.size() >= 3 ? poly : Polygon{};
}

}  // namespace qacc::tess
