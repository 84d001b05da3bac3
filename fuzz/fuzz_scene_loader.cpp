// Fuzz target: scene text → the strict loader (every object type). Bad input must end in a
// SceneError; anything else (a crash, a sanitizer report, another exception) is a finding.
// Files named by the scene resolve against the seed corpus directory (scenes/).
#include <cstddef>
#include <cstdint>
#include <string>
#include <vector>

#include "modeling/loader/scene_loader.h"
#include "modeling/scene/scene_error.h"
#include "fuzz/json_mutator.h"

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  // Small limits: the fuzzer looks for crashes, not for the scenes that are merely slow.
  qacc::Limits limits;
  limits.max_input_bytes = 1 << 20;
  limits.max_primitives = 20000;
  limits.max_cells = 20000;
  limits.max_triangles = 100000;
  limits.max_clip_work = 10000000;  // about 30 ms of setup: up to 82 clip planes on one primitive
  try {
    qacc::parseScene(std::string(reinterpret_cast<const char*>(data), size), "fuzz.json",
                     QACC_SOURCE_DIR "/scenes", limits);
  } catch (const qacc::SceneError&) {
  }
  return 0;
}

// JSON-aware mutations (fuzz/json_mutator.h), with the format's words from the dictionary.
extern "C" std::size_t LLVMFuzzerCustomMutator(std::uint8_t* data, std::size_t size, std::size_t max_size,
                                               unsigned int seed) {
  static const std::vector<std::string> words = qacc::fuzz::dictionaryWords(QACC_SOURCE_DIR "/fuzz/scene.dict");
  return qacc::fuzz::mutateJson(data, size, max_size, seed, words);
}
