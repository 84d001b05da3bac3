#include "tools/engines/image_size.h"

#include <stdexcept>
#include <string>

namespace qacc {

void checkImageSize(int width, int height) {
  if ((width != 0) != (height != 0)) throw std::invalid_argument("--width and --height go together");
  const std::string size = std::to_string(width) + "x" + std::to_string(height);
  if (width < 0 || height < 0)
    throw std::invalid_argument("image size " + size + ": --width and --height are at least 1");
  if (width > kMaxImageSide || height > kMaxImageSide || (long long)width * height > kMaxImagePixels)
    throw std::invalid_argument("image size " + size + " is over the limit (" + std::to_string(kMaxImageSide) +
                                " per side, " + std::to_string(kMaxImagePixels) + " pixels)");
}

void applyImageSize(Scene& scene, int width, int height) {
  checkImageSize(width, height);
  if (width == 0) return;
  scene.width = width;
  scene.height = height;
}

}  // namespace qacc
