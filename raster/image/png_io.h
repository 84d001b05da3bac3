// PNG reading and writing through libpng: 8-bit RGB/gray colour, 16-bit gray (object ids).
#pragma once
#include <string>

#include "raster/image/image.h"

namespace qacc {

// Writes 1 (gray) or 3 (RGB) channel 8-bit images. Throws std::runtime_error on failure.
void writePng(const std::string& path, const Image8& img);
// Writes a 1-channel 16-bit grayscale image.
void writePng16(const std::string& path, const Image16& img);
// Reads an 8-bit PNG as RGB (palette, gray and alpha are converted; 16-bit is stripped).
Image8 readPng(const std::string& path);
// Reads a 16-bit (or 8-bit) grayscale PNG into 16-bit values.
Image16 readPng16(const std::string& path);

}  // namespace qacc
