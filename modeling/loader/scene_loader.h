// Loading of `qacc-scene/1` files (design §6), strict: every problem is refused with a
// SceneError "FILE: /json/path: problem" (unknown keys or types, wrong arity, wrong JSON
// types, NaN/inf, non-positive sizes, singular transforms, unknown materials, images over
// the size limits below, missing files, JSON syntax errors with line and column).
// The format is documented in docs/SCENES.md.
#pragma once
#include <string>

#include "modeling/scene/scene.h"
#include "modeling/support/limits.h"

namespace qacc {

// Image size limits (documented in docs/SCENES.md).
constexpr int kMaxImageSide = 16384;                          // width, height <= 16384
constexpr long long kMaxImagePixels = 64LL * 1024 * 1024;     // width * height <= 64 Mpixel
// Perspective cameras: far / near <= 1e5 (depth precision of the window-space quadrics).
constexpr double kMaxFarNearRatio = 1e5;

// Reads and parses a scene file; relative paths inside it resolve against its directory.
// Input over `limits` is refused with the limit and the option that raises it.
Scene loadScene(const std::string& path, const Limits& limits = Limits{});
// Parses scene text; `file` names it in messages, `directory` resolves relative paths.
Scene parseScene(const std::string& text, const std::string& file, const std::string& directory,
                 const Limits& limits = Limits{});

}  // namespace qacc
