// Narrow widths degrade gracefully: stepping any datapath width down on gallery never
// raises the error by a jump where a cap or clip decision flips wholesale, and the
// accelerator's cap pixels stay within the error budget of the default's (which equals the
// reference's: 0 wrong pixels). Before the quadric datapath had a local depth origin,
// value_bits = 16 turned every solid into caps (a quarter of the image spurious at once).
#include <gtest/gtest.h>

#include <string>
#include <utility>
#include <vector>

#include <nlohmann/json.hpp>

#include "hw_model/engines/functional_engine.h"
#include "hw_model/report/accuracy_report.h"
#include "modeling/loader/scene_loader.h"
#include "raster/reference/reference_renderer.h"

using namespace qacc;

namespace {

struct Step {
  std::vector<std::pair<std::string, int>> set;
};

void checkChain(const std::string& name, const std::vector<Step>& steps) {
  Scene scene = loadScene(std::string(QACC_SOURCE_DIR) + "/scenes/gallery.json");
  scene.width = 200;
  scene.height = 150;
  const FrameBuffer ref = renderReference(scene, 0);
  const HwRender base = renderHw(scene, HwConfig(), 0);
  const AccuracyReport a0 = accuracyReport(ref, base.fb, scene.camera);
  ASSERT_EQ(a0.wrong_object + a0.pinholes + a0.spurious, 0u) << a0.line();
  double previous = 0;
  for (const Step& s : steps) {
    HwConfig c;
    std::string label;
    for (const auto& [k, v] : s.set) {
      setHwConfigKey(c, k, nlohmann::json(v), "test");
      label += k + "=" + std::to_string(v) + " ";
    }
    checkHwConfig(c, "test");
    const HwRender r = renderHw(scene, c, 0);
    const AccuracyReport a = accuracyReport(ref, r.fb, scene.camera);
    const double wrong = 100.0 * a.wrong_fraction;
    // No wholesale flip: one 2-bit step adds at most 6 percentage points of wrong pixels.
    EXPECT_LE(wrong, previous + 6.0) << name << ": " << label << a.line();
    // Cap pixels beyond the default's stay within the error budget: twice the wrong pixels
    // plus 5 % of the covered pixels (a cap shown on the right object instead of its surface
    // is a shading error, not a coverage one). Solids turned into caps wholesale break it.
    const double extraCaps = double(r.stats.pixels.caps) - double(base.stats.pixels.caps);
    EXPECT_LE(extraCaps, 2.0 * double(a.wrong_object + a.pinholes + a.spurious) + 0.05 * double(a.reference_covered)) << name << ": " << label << r.stats.pixels.caps
                                                                           << " caps, default " << base.stats.pixels.caps;
    EXPECT_EQ(r.stats.overflow.total(), 0u) << name << ": " << label;
    previous = wrong;
  }
}

std::vector<Step> range(const std::string& key, int from, int to, int step) {
  std::vector<Step> s;
  for (int v = from; v >= to; v -= step) s.push_back({{{key, v}}});
  return s;
}

}  // namespace

TEST(WidthDegradation, ValueBits) { checkChain("value_bits", range("value_bits", 30, 12, 2)); }
TEST(WidthDegradation, ClipBits) { checkChain("clip_bits", range("clip_bits", 30, 8, 2)); }
TEST(WidthDegradation, InterpFracBits) { checkChain("interp_frac_bits", range("interp_frac_bits", 22, 0, 2)); }
TEST(WidthDegradation, ZbufferBits) { checkChain("zbuffer_bits", range("zbuffer_bits", 22, 8, 2)); }
TEST(WidthDegradation, DepthFracBits) {
  std::vector<Step> s;
  for (int v = 26; v >= 12; v -= 2) s.push_back({{{"depth_frac_bits", v}, {"zbuffer_bits", std::min(v, 24)}}});
  checkChain("depth_frac_bits", s);
}
TEST(WidthDegradation, AllWidthsTogether) {
  std::vector<Step> s;
  for (int v = 30; v >= 12; v -= 2)
    s.push_back({{{"value_bits", v}, {"delta_bits", 2 * v}, {"interp_acc_bits", 2 * v + 26}, {"clip_bits", v}}});
  checkChain("all", s);
}
