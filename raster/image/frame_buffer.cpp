#include "raster/image/frame_buffer.h"

#include <algorithm>
#include <cstring>

namespace qacc {

FrameBuffer::Background::Background(const std::array<std::uint8_t, 3>& c) {
  for (std::size_t i = 0; i < 48; i += 3) {
    pattern[i] = c[0];
    pattern[i + 1] = c[1];
    pattern[i + 2] = c[2];
  }
}

FrameBuffer::FrameBuffer(int w, int h, const Background& bg) : FrameBuffer(uninitialised(w, h)) {
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

namespace {

// n pixels of the background colour from `out` (3 bytes each): 16 pixels at a time from its
// 48-byte pattern, which the compiler stores in 16-byte words (a byte at a time took a third
// of clearRect's time on a 1920x1080 frame).
void fillRgb(std::uint8_t* out, std::size_t n, const FrameBuffer::Background& bg) {
  const std::uint8_t* pattern = bg.pattern;
  std::size_t bytes = 3 * n;
  for (; bytes >= 48; bytes -= 48, out += 48) std::memcpy(out, pattern, 48);
  std::memcpy(out, pattern, bytes);
}

}  // namespace

void FrameBuffer::clearRect(int x0, int y0, int x1, int y1, const Background& bg) {
  if (x1 <= x0) return;
  const std::size_t n = std::size_t(x1 - x0);
  for (int y = y0; y < y1; ++y) {
    const std::size_t row = std::size_t(y) * std::size_t(width) + std::size_t(x0);
    std::fill_n(depth.begin() + std::ptrdiff_t(row), n, std::numeric_limits<double>::infinity());
    std::fill_n(object.begin() + std::ptrdiff_t(row), n, -1);
    std::fill_n(primitive.begin() + std::ptrdiff_t(row), n, -1);
    fillRgb(color.data.data() + row * 3, n, bg);
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
