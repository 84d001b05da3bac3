#include "raster/metrics/depth_error.h"

#include <algorithm>
#include <cmath>
#include <stdexcept>

namespace qacc {

double windowDepthToView(const Camera& c, double z) {
  const double n = c.near, f = c.far;
  if (c.type == Camera::Type::Orthographic) return n + z * (f - n);
  // z_ndc = 2 z − 1 = (f + n)/(f − n) − 2 f n / ((f − n) d)  ⇒  d = f n / (f − z (f − n)).
  return f * n / (f - z * (f - n));
}

namespace {
void checkSizes(const FrameBuffer& a, const FrameBuffer& b) {
  if (a.width != b.width || a.height != b.height || a.depth.size() != b.depth.size() ||
      a.object.size() != b.object.size())
    throw std::invalid_argument("depthError: frame buffers differ in size");
}
bool comparable(const FrameBuffer& a, const FrameBuffer& b, std::size_t i) {
  return a.object[i] >= 0 && a.object[i] == b.object[i] && std::isfinite(a.depth[i]) && std::isfinite(b.depth[i]);
}
}  // namespace

DepthError depthError(const FrameBuffer& reference, const FrameBuffer& test, const Camera& camera, int bits) {
  checkSizes(reference, test);
  DepthError e;
  e.bits = bits;
  const double scale = std::ldexp(1.0, bits) - 1.0;
  double sw = 0, sv = 0;
  for (std::size_t i = 0; i < reference.pixels(); ++i) {
    if (!comparable(reference, test, i)) continue;
    ++e.pixels;
    const double dw = std::abs(reference.depth[i] - test.depth[i]);
    const double dv = std::abs(windowDepthToView(camera, reference.depth[i]) - windowDepthToView(camera, test.depth[i]));
    e.max_window = std::max(e.max_window, dw);
    e.max_view = std::max(e.max_view, dv);
    sw += dw;
    sv += dv;
  }
  if (e.pixels) {
    e.mean_window = sw / double(e.pixels);
    e.mean_view = sv / double(e.pixels);
  }
  e.max_lsb = e.max_window * scale;
  e.mean_lsb = e.mean_window * scale;
  e.max_z24 = std::ldexp(e.max_window, 24);
  e.mean_z24 = std::ldexp(e.mean_window, 24);
  return e;
}

ImageF depthErrorMap(const FrameBuffer& reference, const FrameBuffer& test) {
  checkSizes(reference, test);
  ImageF out(reference.width, reference.height, 1, 0.0f);
  for (std::size_t i = 0; i < reference.pixels(); ++i)
    if (comparable(reference, test, i)) out.data[i] = float(std::abs(reference.depth[i] - test.depth[i]));
  return out;
}

}  // namespace qacc
