#include "tools/compare/side_by_side.h"

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <filesystem>

#include "raster/image/heat_map.h"
#include "raster/image/png_io.h"
#include "raster/metrics/coverage_error.h"
#include "tools/compare/number_format.h"
#include "tools/compare/report_files.h"
#include "tools/report/build_info.h"
#include "tools/report/python_tool.h"

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

// |ΔY| as an 8-bit gray image (0..255 luma levels); the script maps it to colour.
Image8 lumaError(const FrameBuffer& ref, const FrameBuffer& t) {
  const ImageF d = lumaDifference(ref.color, t.color);
  Image8 out(d.width, d.height, 1);
  for (std::size_t i = 0; i < d.data.size(); ++i)
    out.data[i] = std::uint8_t(std::clamp(std::lround(d.data[i]), 0L, 255L));
  return out;
}

nlohmann::json metricsJson(const Row& r) {
  return {{"psnr_db", jnum(r.m.psnr)},
          {"ssim", jnum(r.m.ssim)},
          {"silhouette_hausdorff_px", jnum(r.m.hausdorff)},
          {"wrong_object_px", r.m.wrong},
          {"pinholes_px", r.m.pinholes},
          {"spurious_px", r.m.spurious}};
}

}  // namespace

std::size_t shownFacetLevel(const nlohmann::json& jEqual, const std::vector<Row>& facets) {
  std::size_t shown = facets.size() - 1;
  for (const auto& j : jEqual)
    if (j["metric"] == "silhouette_hausdorff_px" && j.value("reached", false) && j.contains("between_rows"))
      shown = j["between_rows"][1].get<std::size_t>();
  return shown;
}

void writeSideBySidePanels(const std::string& dir, const SideBySideInfo& info, const FrameBuffer& ref, const Row& hw,
                           const Row& fr) {
  namespace fs = std::filesystem;
  const fs::path panels = fs::path(dir) / "panels";
  fs::create_directories(panels);
  writePng((panels / "reference.png").string(), ref.color);
  writePng((panels / "quadrics.png").string(), hw.fb.color);
  writePng((panels / "facets.png").string(), fr.fb.color);
  writePng((panels / "quadrics_luma_error.png").string(), lumaError(ref, hw.fb));
  writePng((panels / "facets_luma_error.png").string(), lumaError(ref, fr.fb));
  writePng((panels / "facets_coverage.png").string(), coverageOverlay(ref, fr.fb));
  nlohmann::json j;
  j["format"] = "qacc-side-by-side/1";
  j["qacc_version"] = qaccVersion();
  j["scene"] = info.scene;
  j["width"] = ref.width;
  j["height"] = ref.height;
  j["luma_error_scale"] = {{"unit", "|delta Y| (Rec. 601 luma, 8-bit levels)"}, {"max", 64}};
  j["coverage_colours"] = {{"wrong object", "#ff2828"}, {"pinhole", "#ffe600"}, {"spurious", "#00dcff"}};
  j["reference"] = {{"image", "panels/reference.png"}, {"engine", "reference: exact double-precision ray casting"}};
  j["quadrics"] = {{"image", "panels/quadrics.png"},
                   {"error_image", "panels/quadrics_luma_error.png"},
                   {"engine", "accelerator (hw), " + std::to_string(info.quadric_primitives) + " quadrics"},
                   {"config", info.hw_config},
                   {"cycles", hw.cycles},
                   {"metrics", metricsJson(hw)}};
  j["facets"] = {{"image", "panels/facets.png"},
                 {"error_image", "panels/facets_luma_error.png"},
                 {"coverage_image", "panels/facets_coverage.png"},
                 {"engine", "triangles via " + info.gl_renderer + ", " + info.facet_shading + " shading"},
                 {"setting", fr.setting()},
                 {"tolerance_px", fr.tolerance_px},
                 {"level", fr.level},
                 {"triangles", fr.primitives},
                 {"cycles", fr.cycles},
                 {"metrics", metricsJson(fr)}};
  writeText((fs::path(dir) / "side_by_side.json").string(), j.dump(2) + "\n");
}

std::string composeSideBySide(const std::string& dir) { return runPythonTool("compose_side_by_side.py", dir); }

}  // namespace qacc::compare
