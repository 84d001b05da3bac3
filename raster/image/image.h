// Image<T>: a width x height x channels array of T, row-major, row 0 at the top.
#pragma once
#include <cstddef>
#include <cstdint>
#include <vector>

#include "raster/image/default_init_allocator.h"

namespace qacc {

template <typename T>
struct Image {
  int width = 0;
  int height = 0;
  int channels = 1;
  UninitVector<T> data;

  Image() = default;
  Image(int w, int h, int c, T fill = T()) : width(w), height(h), channels(c),
      data(std::size_t(w) * std::size_t(h) * std::size_t(c), fill) {}
  // Every sample left uninitialised: for a producer that writes all of them.
  static Image uninitialised(int w, int h, int c) {
    Image img;
    img.width = w;
    img.height = h;
    img.channels = c;
    img.data.resize(std::size_t(w) * std::size_t(h) * std::size_t(c));
    return img;
  }

  std::size_t index(int x, int y, int c = 0) const {
    return (std::size_t(y) * std::size_t(width) + std::size_t(x)) * std::size_t(channels) + std::size_t(c);
  }
  T& at(int x, int y, int c = 0) { return data[index(x, y, c)]; }
  const T& at(int x, int y, int c = 0) const { return data[index(x, y, c)]; }
  std::size_t pixels() const { return std::size_t(width) * std::size_t(height); }
  bool sameShape(const Image& o) const { return width == o.width && height == o.height && channels == o.channels; }
};

using Image8 = Image<std::uint8_t>;
using Image16 = Image<std::uint16_t>;
using ImageF = Image<float>;

}  // namespace qacc
