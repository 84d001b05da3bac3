// ReferenceCache: reference frames on disk, keyed by a content hash of what they depend on
// (the scene text, the bytes of every file the scene names, the image size and the
// reference renderer's version, kReferenceRendererVersion), so that a sweep renders the
// reference once per (scene, size) and never again, and a changed scene or PDB file is
// never served a stale frame. One entry is KEY.frame (colour, window depth, object and
// primitive per pixel, exact) and KEY.png (the colour, for people). Entries are written
// to a temporary file and renamed, so concurrent shards never read a partial entry.
// Directory: `--cache DIR`, else $QACC_CACHE, else ~/.cache/qacc.
#pragma once
#include <cstddef>
#include <functional>
#include <string>

#include "modeling/scene/scene.h"
#include "raster/image/frame_buffer.h"

namespace qacc {

class ReferenceCache {
 public:
  // `dir` empty: $QACC_CACHE, else $HOME/.cache/qacc.
  explicit ReferenceCache(const std::string& dir = "");
  const std::string& directory() const { return dir_; }
  // The key of a scene parsed from `sceneText` (files named in it resolve against
  // `sceneDir`) at width x height.
  static std::string key(const std::string& sceneText, const std::string& sceneDir, int width, int height);
  // The reference frame of the scene parsed from sceneText at width x height: from the
  // cache, or made by `scene()` (called only on a miss), rendered and stored. With
  // `primitiveIds` false the frame comes without its primitive ids (`primitive` empty),
  // for a caller that reads colour, depth and objects only, such as the accuracy line: a
  // frame-sized buffer (4 bytes per pixel) it would not use is neither read nor kept.
  FrameBuffer get(const std::string& sceneText, const std::string& sceneDir, int width, int height,
                  const std::function<Scene()>& scene, int threads, bool primitiveIds = true);
  // Renders every reference and stores none (measures what the cache saves).
  void disable() { disabled_ = true; }
  bool disabled() const { return disabled_; }
  std::size_t hits() const { return hits_; }
  std::size_t renders() const { return renders_; }

 private:
  std::string dir_;
  std::size_t hits_ = 0, renders_ = 0;
  bool disabled_ = false;
};

// Exact binary form of a frame buffer (KEY.frame); read returns false for a missing or bad
// file (any size but the one its header implies), and leaves out the primitive ids when
// `primitiveIds` is false.
void writeFrameBuffer(const std::string& path, const FrameBuffer& fb);
bool readFrameBuffer(const std::string& path, FrameBuffer& fb, bool primitiveIds = true);

}  // namespace qacc
