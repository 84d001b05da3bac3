#include "tools/compare/side_by_side.h"

#include <cstdint>

#include "raster/image/heat_map.h"
#include "raster/image/png_io.h"
#include "raster/metrics/coverage_error.h"

namespace qacc::compare {

namespace {

Image8 coverageOverlay(const FrameBuffer& ref, const FrameBuffer& t) {
  const Image8 mask = coverageErrorMask(ref, t);
  Image8 out(ref.width, ref.height, 3);
  for (std::size_t i = 0; i < ref.pixels(); ++i) {
    std::uint8_t c[3];
    for (int k = 0; k < 3; ++k) c[k] = std::uint8_t(ref.color.data[i * 3 + k] / 4);  // dimmed reference
    switch (mask.data[i]) {
      case 1: c[0] = 255; c[1] = 40; c[2] = 40; break;    // wrong object: red
      case 2: c[0] = 255; c[1] = 230; c[2] = 0; break;    // pinhole: yellow
      case 3: c[0] = 0; c[1] = 220; c[2] = 255; break;    // spurious: cyan
      default: break;
    }
    for (int k = 0; k < 3; ++k) out.data[i * 3 + k] = c[k];
  }
  return out;
}

}  // namespace

std::size_t shownFacetLevel(const nlohmann::json& jEqual, const std::vector<Row>& facets) {
  int shown = int(facets.size()) - 1;
  for (const auto& j : jEqual)
    if (j["metric"] == "psnr_db" && j.value("reached", false)) {
      for (std::size_t i = 0; i < facets.size(); ++i)
        if (facets[i].level == j["level"].get<int>()) shown = int(i);
    }
  return std::size_t(shown);
}

void writeSideBySide(const std::string& path, const FrameBuffer& ref, const Row& hw, const Row& fr) {
  const int W = ref.width, H = ref.height;
  Image8 sbs(3 * W, 2 * H, 3, 0);
  blit(sbs, ref.color, 0, 0);
  blit(sbs, hw.fb.color, W, 0);
  blit(sbs, fr.fb.color, 2 * W, 0);
  blit(sbs, heatMap(lumaDifference(ref.color, hw.fb.color), 64.0), 0, H);
  blit(sbs, heatMap(lumaDifference(ref.color, fr.fb.color), 64.0), W, H);
  blit(sbs, coverageOverlay(ref, fr.fb), 2 * W, H);
  writePng(path, sbs);
}

}  // namespace qacc::compare
