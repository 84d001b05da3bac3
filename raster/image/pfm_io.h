// Portable Float Map I/O: 1-channel ("Pf") little-endian float, rows stored bottom-up as
// the format requires; in memory row 0 is the top row like every Image.
#pragma once
#include <string>

#include "raster/image/image.h"

namespace qacc {

void writePfm(const std::string& path, const ImageF& img);
ImageF readPfm(const std::string& path);

}  // namespace qacc
