// Fuzz target: accelerator configuration text → parseHwConfig. Bad input must end in
// std::invalid_argument naming the file and the key.
#include <cstddef>
#include <cstdint>
#include <stdexcept>
#include <string>
#include <vector>

#include "hw_model/config/hw_config.h"
#include "fuzz/json_mutator.h"

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  try {
    qacc::parseHwConfig(std::string(reinterpret_cast<const char*>(data), size), "fuzz.json");
  } catch (const std::invalid_argument&) {
  }
  return 0;
}

// JSON-aware mutations (fuzz/json_mutator.h), with the format's words from the dictionary.
extern "C" std::size_t LLVMFuzzerCustomMutator(std::uint8_t* data, std::size_t size, std::size_t max_size,
                                               unsigned int seed) {
  static const std::vector<std::string> words = qacc::fuzz::dictionaryWords(QACC_SOURCE_DIR "/fuzz/hw_config.dict");
  return qacc::fuzz::mutateJson(data, size, max_size, seed, words);
}
