#include "raster/image/frame_buffer.h"

#include <algorithm>

namespace qacc {

FrameBuffer::FrameBuffer(int w, int h, const std::array<std::uint8_t, 3>& bg) : FrameBuffer(uninitialised(w, h)) {
  clearRect(0, 0, w, h, bg);
}

FrameBuffer FrameBuffer::uninitialised(int w, int h) {
  FrameBuffer fb;
  fb.width = w;
  fb.height = h;
  fb.color = Image8::uninitialised(w, h, 3);
  fb.depth.resize(fb.pixels());
  fb.object.resize(fb.pixels());
  fb.primitive.resize(fb.pixels());
  return fb;
}

void FrameBuffer::clearRect(int x0, int y0, int x1, int y1, const std::array<std::uint8_t, 3>& bg) {
  if (x1 <= x0) return;
  const std::size_t n = std::size_t(x1 - x0);
  for (int y = y0; y < y1; ++y) {
    const std::size_t row = std::size_t(y) * std::size_t(width) + std::size_t(x0);
    std::fill_n(depth.begin() + std::ptrdiff_t(row), n, std::numeric_limits<double>::infinity());
    std::fill_n(object.begin() + std::ptrdiff_t(row), n, -1);
    std::fill_n(primitive.begin() + std::ptrdiff_t(row), n, -1);
    std::uint8_t* c = color.data.data() + row * 3;
    for (std::size_t i = 0; i < n; ++i, c += 3) {
      c[0] = bg[0];
      c[1] = bg[1];
      c[2] = bg[2];
    }
  }
}

std::size_t FrameBuffer::covered() const {
  return std::size_t(std::count_if(object.begin(), object.end(), [](std::int32_t o) { return o >= 0; }));
}

Image16 FrameBuffer::idImage() const {
  Image16 img(width, height, 1);
  for (std::size_t i = 0; i < pixels(); ++i)
    img.data[i] = static_cast<std::uint16_t>(std::min<std::int64_t>(std::int64_t(object[i]) + 1, 65535));
  return img;
}

ImageF FrameBuffer::depthImage() const {
  ImageF img(width, height, 1);
  for (std::size_t i = 0; i < pixels(); ++i) img.data[i] = static_cast<float>(depth[i]);
  return img;
}

}  // namespace qacc
