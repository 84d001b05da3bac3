// Fuzz target: a scene rendered tiny (24x18) by the reference, hw and hw-cycle. A scene the
// loader accepts must render without a crash or sanitizer report, and hw and hw-cycle must
// produce the same image (they are bit-identical by construction).
#include <cstddef>
#include <cstdint>
#include <cstdlib>
#include <string>

#include "hw_model/engines/cycle_engine.h"
#include "hw_model/engines/functional_engine.h"
#include "modeling/loader/scene_loader.h"
#include "modeling/scene/scene_error.h"
#include "raster/reference/reference_renderer.h"

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  qacc::Limits limits;
  limits.max_input_bytes = 1 << 20;
  limits.max_primitives = 2000;
  limits.max_cells = 5000;
  qacc::Scene scene;
  try {
    scene = qacc::parseScene(std::string(reinterpret_cast<const char*>(data), size), "fuzz.json",
                             QACC_SOURCE_DIR "/scenes", limits);
  } catch (const qacc::SceneError&) {
    return 0;
  }
  scene.width = 24;
  scene.height = 18;
  qacc::renderReference(scene, 1);
  const qacc::HwConfig cfg;
  const qacc::HwRender a = qacc::renderHw(scene, cfg, 1);
  const qacc::HwRender b = qacc::renderHwCycle(scene, cfg, 1);
  if (!(a.fb.color.data == b.fb.color.data) || a.fb.object != b.fb.object) std::abort();
  return 0;
}
