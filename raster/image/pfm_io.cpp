#include "raster/image/pfm_io.h"

#include <cstdio>
#include <fstream>
#include <stdexcept>

namespace qacc {

void writePfm(const std::string& path, const ImageF& img) {
  if (img.channels != 1) throw std::runtime_error("writePfm: 1 channel");
  std::ofstream out(path, std::ios::binary);
  if (!out) throw std::runtime_error("cannot open '" + path + "' for writing");
  out << "Pf\n" << img.width << " " << img.height << "\n-1.0\n";
  for (int y = img.height - 1; y >= 0; --y)
    out.write(reinterpret_cast<const char*>(&img.data[img.index(0, y)]),
              std::streamsize(sizeof(float) * img.width));
  if (!out) throw std::runtime_error("writing '" + path + "' failed");
}

ImageF readPfm(const std::string& path) {
  std::ifstream in(path, std::ios::binary);
  if (!in) throw std::runtime_error("cannot open '" + path + "'");
  std::string magic;
  int w = 0, h = 0;
  double scale = 0;
  in >> magic >> w >> h >> scale;
  in.get();
  if (magic != "Pf" || w <= 0 || h <= 0 || scale >= 0)
    throw std::runtime_error("'" + path + "' is not a little-endian 1-channel PFM");
  ImageF img(w, h, 1);
  for (int y = h - 1; y >= 0; --y)
    in.read(reinterpret_cast<char*>(&img.data[img.index(0, y)]), std::streamsize(sizeof(float) * w));
  if (!in) throw std::runtime_error("'" + path + "' is truncated");
  return img;
}

}  // namespace qacc
