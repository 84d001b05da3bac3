#include "raster/image/frame_buffer.h"

#include <algorithm>

namespace qacc {

FrameBuffer::FrameBuffer(int w, int h, const std::array<std::uint8_t, 3>& bg)
    : width(w), height(h), color(w, h, 3), depth(std::size_t(w) * h, std::numeric_limits<double>::infinity()),
      object(std::size_t(w) * h, -1), primitive(std::size_t(w) * h, -1) {
  // Background colour: one pixel, then the filled prefix doubles (memcpy-speed fill).
  const std::size_t n = color.data.size();
  if (n == 0) return;
  std::copy(bg.begin(), bg.end(), color.data.begin());
  for (std::size_t done = 3; done < n;) {
    const std::size_t k = std::min(done, n - done);
    std::copy_n(color.data.begin(), k, color.data.begin() + std::ptrdiff_t(done));
    done += k;
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
