// FrameBuffer: what every renderer produces — colour (8-bit sRGB RGB), window depth
// (+inf where nothing was hit) and the object / primitive index per pixel (-1 = none).
#pragma once
#include <array>
#include <cstdint>
#include <limits>
#include <vector>

#include "raster/image/image.h"

namespace qacc {

struct FrameBuffer {
  int width = 0;
  int height = 0;
  Image8 color;                      // 3 channels, sRGB
  UninitVector<double> depth;         // window z in [0, 1], +inf = background
  UninitVector<std::int32_t> object;  // scene object index, -1 = background
  UninitVector<std::int32_t> primitive;  // primitive index, -1 = background

  // The background colour with the 48-byte pattern (16 pixels) clearRect writes it from, built
  // once per frame by a renderer that clears many rectangles (a tile's or a row's background:
  // building it for every rectangle took most of clearRect's time on a 1920x1080 frame).
  struct Background {
    Background(const std::array<std::uint8_t, 3>& rgb);  // implicit: a colour is a background
    Background(std::uint8_t r, std::uint8_t g, std::uint8_t b) : Background(std::array<std::uint8_t, 3>{r, g, b}) {}
    std::uint8_t pattern[48];  // the colour's three bytes, 16 times
  };

  FrameBuffer() = default;
  FrameBuffer(int w, int h, const Background& background);
  // Every pixel left uninitialised: for a renderer that writes each one exactly once (its
  // tiles clear their own rectangle with clearRect, in parallel, then draw) — no
  // frame-sized clearing in one thread before the frame.
  static FrameBuffer uninitialised(int w, int h);
  // Background in [x0, x1) x [y0, y1): colour, depth +inf, no object, no primitive.
  void clearRect(int x0, int y0, int x1, int y1, const Background& background);

  std::size_t pixels() const { return std::size_t(width) * std::size_t(height); }
  std::size_t covered() const;
  // 16-bit id image: object index + 1 (0 = nothing); ids above 65534 saturate.
  Image16 idImage() const;
  // Window depth as float (+inf where nothing was hit).
  ImageF depthImage() const;
};

}  // namespace qacc
