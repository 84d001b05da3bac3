#include "raster/metrics/coverage_error.h"

#include <stdexcept>

namespace qacc {

namespace {
void checkSizes(const FrameBuffer& a, const FrameBuffer& b) {
  if (a.width != b.width || a.height != b.height || a.object.size() != b.object.size())
    throw std::invalid_argument("coverageError: frame buffers differ in size");
}
int classify(std::int32_t r, std::int32_t t) {
  if (r >= 0 && t >= 0) return r == t ? 0 : 1;
  if (r >= 0) return 2;
  if (t >= 0) return 3;
  return 0;
}
}  // namespace

CoverageError coverageError(const FrameBuffer& reference, const FrameBuffer& test) {
  checkSizes(reference, test);
  CoverageError e;
  e.pixels = reference.pixels();
  for (std::size_t i = 0; i < e.pixels; ++i) {
    const std::int32_t r = reference.object[i], t = test.object[i];
    if (r >= 0) ++e.reference_covered;
    if (r >= 0 || t >= 0) ++e.union_covered;
    switch (classify(r, t)) {
      case 1: ++e.wrong_object; break;
      case 2: ++e.pinholes; break;
      case 3: ++e.spurious; break;
      default: break;
    }
  }
  return e;
}

Image8 coverageErrorMask(const FrameBuffer& reference, const FrameBuffer& test) {
  checkSizes(reference, test);
  Image8 m(reference.width, reference.height, 1);
  for (std::size_t i = 0; i < reference.pixels(); ++i)
    m.data[i] = std::uint8_t(classify(reference.object[i], test.object[i]));
  return m;
}

}  // namespace qacc
