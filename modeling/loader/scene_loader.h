// Loading of `qacc-scene/1` files (design §6), strict: every problem is refused with a
// SceneError "FILE: /json/path: problem" (unknown keys or types, wrong arity, wrong JSON
// types, NaN/inf, non-positive sizes, singular transforms, unknown materials, images over
// the size limits below, missing files, JSON syntax errors with line and column).
// The format is documented in docs/SCENES.md.
#pragma once
#include <string>

#include "modeling/scene/scene.h"

namespace qacc {

// Image size limits (documented in docs/SCENES.md).
constexpr int kMaxImageSide = 16384;                          // width, height <= 16384
constexpr long long kMaxImagePixels = 64LL * 1024 * 1024;     // width * height <= 64 Mpixel

// Reads and parses a scene file; relative paths inside it resolve against its directory.
Scene loadScene(const std::string& path);
// Parses scene text; `file` names it in messages, `directory` resolves relative paths.
Scene parseScene(const std::string& text, const std::string& file, const std::string& directory);

}  // namespace qacc
