// Loading of `qacc-scene/1` files (design §6), strict: every problem is refused with a
// SceneError "FILE: /json/path: problem" (unknown keys or types, wrong arity, wrong JSON
// types, NaN/inf, non-positive sizes, singular transforms, unknown materials, images over
// the size limits below, missing files, JSON syntax errors with line and column).
// The format is documented in docs/SCENES.md.
#pragma once
#include <string>

#include "modeling/loader/object_registry.h"
#include "modeling/loader/view_culling.h"
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
// `view`: view culling (view_culling.h), on by default at the file's image size.
Scene loadScene(const std::string& path, const Limits& limits = Limits{}, const ViewCulling& view = ViewCulling{});
// The text of a scene file, read with the input bound (SceneError naming the file when it
// cannot be read), and the directory its relative paths resolve against.
std::string readSceneText(const std::string& path, const Limits& limits = Limits{});
std::string sceneDirectory(const std::string& path);
// Parses scene text; `file` names it in messages, `directory` resolves relative paths.
Scene parseScene(const std::string& text, const std::string& file, const std::string& directory,
                 const Limits& limits = Limits{}, const ViewCulling& view = ViewCulling{});
// Builds an object nested inside another one (a part of a `csg` object) as the loader builds a
// top-level object: the type's builder, then its own `clip`, `transform`, `material` and
// `solid`. The primitives are in the parent's local frame and belong to scene object
// `objectIndex`. Objects with a non-quadric exact surface are refused.
std::vector<Primitive> buildObject(const JsonNode& o, ObjectContext& parent, int objectIndex);

}  // namespace qacc
