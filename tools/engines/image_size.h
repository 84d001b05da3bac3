// The --width / --height override of a scene's image size: one check for every command
// that takes a size (render, batch, compare, bench). Both are given or neither (0 and 0:
// the scene's own size); each is from 1 to kMaxImageSide and their product is at most
// kMaxImagePixels, the limits the scene loader applies to the file's own size.
#pragma once
#include "modeling/loader/scene_loader.h"  // kMaxImageSide, kMaxImagePixels
#include "modeling/scene/scene.h"

namespace qacc {

// Throws std::invalid_argument (printed as "qacc: error: ...") for a size the commands refuse.
void checkImageSize(int width, int height);
// checkImageSize, then the scene takes the size when one is given.
void applyImageSize(Scene& scene, int width, int height);

}  // namespace qacc
