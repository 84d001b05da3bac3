#include "raster/image/png_io.h"

#include <png.h>

#include <cstdio>
#include <memory>
#include <stdexcept>

namespace qacc {
namespace {

struct File {
  std::FILE* f;
  ~File() { if (f) std::fclose(f); }
};

[[noreturn]] void pngFail(png_structp, png_const_charp msg) { throw std::runtime_error(msg); }
void pngWarn(png_structp, png_const_charp) {}

template <typename T>
void writeAny(const std::string& path, const Image<T>& img, int bitDepth, int colorType) {
  File file{std::fopen(path.c_str(), "wb")};
  if (!file.f) throw std::runtime_error("cannot open '" + path + "' for writing");
  png_structp png = png_create_write_struct(PNG_LIBPNG_VER_STRING, nullptr, pngFail, pngWarn);
  png_infop info = png_create_info_struct(png);
  try {
    png_init_io(png, file.f);
    png_set_IHDR(png, info, img.width, img.height, bitDepth, colorType, PNG_INTERLACE_NONE,
                 PNG_COMPRESSION_TYPE_DEFAULT, PNG_FILTER_TYPE_DEFAULT);
    // The "up" filter (each row as its difference from the row above) and zlib level 3:
    // libpng's default (an adaptive choice among the five filters per row, level 6) took
    // 180 ms for molecule's 1920x1080 colour image, more than the frame; this takes 50 ms for
    // a file 3 % larger (sphereflake: 159 -> 46 ms, 13 % larger; docs/PERFORMANCE.md "PNG
    // writing"). Lossless either way: the pixels read back are the same.
    png_set_filter(png, PNG_FILTER_TYPE_BASE, PNG_FILTER_UP);
    png_set_compression_level(png, 3);
    png_write_info(png, info);
    if (bitDepth == 16) png_set_swap(png);  // our uint16 are host (little-endian) order
    const std::size_t stride = std::size_t(img.width) * img.channels;
    for (int y = 0; y < img.height; ++y)
      png_write_row(png, reinterpret_cast<png_const_bytep>(img.data.data() + stride * y));
    png_write_end(png, nullptr);
  } catch (const std::exception& e) {
    png_destroy_write_struct(&png, &info);
    throw std::runtime_error("writing '" + path + "': " + e.what());
  }
  png_destroy_write_struct(&png, &info);
}

template <typename T>
Image<T> readAny(const std::string& path, bool sixteen) {
  File file{std::fopen(path.c_str(), "rb")};
  if (!file.f) throw std::runtime_error("cannot open '" + path + "'");
  png_structp png = png_create_read_struct(PNG_LIBPNG_VER_STRING, nullptr, pngFail, pngWarn);
  png_infop info = png_create_info_struct(png);
  Image<T> img;
  try {
    png_init_io(png, file.f);
    png_read_info(png, info);
    const int ct = png_get_color_type(png, info);
    const int bd = png_get_bit_depth(png, info);
    if (ct == PNG_COLOR_TYPE_PALETTE) png_set_palette_to_rgb(png);
    if ((ct & PNG_COLOR_MASK_ALPHA) != 0) png_set_strip_alpha(png);
    if (bd < 8) png_set_expand(png);
    if (sixteen) {
      if (ct & PNG_COLOR_MASK_COLOR) png_set_rgb_to_gray_fixed(png, 1, -1, -1);
      if (bd == 16) png_set_swap(png);
      else png_set_expand_16(png);
    } else {
      if (bd == 16) png_set_strip_16(png);
      if (!(ct & PNG_COLOR_MASK_COLOR)) png_set_gray_to_rgb(png);
    }
    png_read_update_info(png, info);
    img = Image<T>(int(png_get_image_width(png, info)), int(png_get_image_height(png, info)),
                   sixteen ? 1 : 3);
    if (png_get_rowbytes(png, info) != std::size_t(img.width) * img.channels * sizeof(T))
      throw std::runtime_error("unexpected PNG layout");
    const std::size_t stride = std::size_t(img.width) * img.channels;
    for (int y = 0; y < img.height; ++y)
      png_read_row(png, reinterpret_cast<png_bytep>(img.data.data() + stride * y), nullptr);
    png_read_end(png, nullptr);
  } catch (const std::exception& e) {
    png_destroy_read_struct(&png, &info, nullptr);
    throw std::runtime_error("reading '" + path + "': " + e.what());
  }
  png_destroy_read_struct(&png, &info, nullptr);
  return img;
}

}  // namespace

void writePng(const std::string& path, const Image8& img) {
  if (img.channels != 1 && img.channels != 3) throw std::runtime_error("writePng: 1 or 3 channels");
  writeAny(path, img, 8, img.channels == 3 ? PNG_COLOR_TYPE_RGB : PNG_COLOR_TYPE_GRAY);
}

void writePng16(const std::string& path, const Image16& img) {
  if (img.channels != 1) throw std::runtime_error("writePng16: 1 channel");
  writeAny(path, img, 16, PNG_COLOR_TYPE_GRAY);
}

Image8 readPng(const std::string& path) { return readAny<std::uint8_t>(path, false); }
Image16 readPng16(const std::string& path) { return readAny<std::uint16_t>(path, true); }

}  // namespace qacc
