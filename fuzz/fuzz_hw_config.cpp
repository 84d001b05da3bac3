// Fuzz target: accelerator configuration text → parseHwConfig. Bad input must end in
// std::invalid_argument naming the file and the key.
#include <cstddef>
#include <cstdint>
#include <stdexcept>
#include <string>

#include "hw_model/config/hw_config.h"

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  try {
    qacc::parseHwConfig(std::string(reinterpret_cast<const char*>(data), size), "fuzz.json");
  } catch (const std::invalid_argument&) {
  }
  return 0;
}
