// Wrong images said nowhere (issue 14), through the whole path: scene text → loader → hw.
#include <gtest/gtest.h>

#include <sstream>
#include <string>

#include "hw_model/engines/functional_engine.h"
#include "hw_model/report/accuracy_report.h"
#include "modeling/loader/scene_loader.h"
#include "raster/reference/reference_renderer.h"

using namespace qacc;

namespace {

Scene capScene(const std::string& clip) {
  return parseScene(R"({"format": "qacc-scene/1", "image": {"width": 160, "height": 120},
    "camera": {"eye": [1.5, 2.5, 4], "target": [0, 0, 0], "up": [0, 1, 0], "near": 0.1, "far": 100},
    "objects": [{"type": "sphere", "center": [0,0,0], "radius": 1, "solid": true, "clip": )" + clip + "}]}",
                    "cap.json", ".");
}

}  // namespace

// A solid whose clip plane is listed twice lost its cap in hw and showed the inner wall
// (27.6 dB here instead of 76; the coverage counts stayed at 0, so the accuracy line did not
// see it). The plane is now added once.
TEST(HwReliability, ClipPlaneListedTwiceKeepsItsCap) {
  const Scene once = capScene("[[0.3, 1, 0.2, -0.1]]");
  const Scene twice = capScene("[[0.3, 1, 0.2, -0.1], [0.3, 1, 0.2, -0.1]]");
  ASSERT_EQ(twice.primitives[0].clip.size(), 1u);
  const HwRender a = renderHw(once, HwConfig(), 2), b = renderHw(twice, HwConfig(), 2);
  EXPECT_TRUE(a.fb.color.data == b.fb.color.data);
  const AccuracyReport r = accuracyReport(renderReference(twice, 2), b.fb, twice.camera);
  EXPECT_GT(r.psnr_db, 60.0) << r.line();
}

// A plane is scale-free, but coefficients near 1e300 were mis-clipped: hw's cap of a solid
// cut by [0.3, 1, 0.2, -0.1] x 1e300 (or x 1e-300) was shaded wrongly (15 dB against the
// reference), and x 1e307 overflowed in the window transform so that both engines drew
// nothing. Planes are normalised by a power of two (exact) when read and at setup.
TEST(HwReliability, ClipPlaneCoefficientsNear1e300AreScaleFree) {
  for (bool solid : {false, true}) {
    Scene unit = capScene("[[0.3, 1, 0.2, -0.1]]");
    unit.primitives[0].solid = solid;
    const FrameBuffer unitRef = renderReference(unit, 2);
    for (double m : {1e300, 1e-300, 1e307, 1e-307}) {
      std::ostringstream clip;
      clip.precision(17);
      clip << "[[" << 0.3 * m << ", " << m << ", " << 0.2 * m << ", " << -0.1 * m << "]]";
      Scene sc = capScene(clip.str());
      sc.primitives[0].solid = solid;
      const std::string what = clip.str() + (solid ? " solid" : "");
      const FrameBuffer ref = renderReference(sc, 2);
      const AccuracyReport same = accuracyReport(unitRef, ref, sc.camera);
      EXPECT_GT(same.reference_covered, 1000u) << what;
      EXPECT_GT(same.psnr_db, 60.0) << what << ": reference against the unit plane: " << same.line();
      const AccuracyReport hw = accuracyReport(ref, renderHw(sc, HwConfig(), 2).fb, sc.camera);
      EXPECT_GT(hw.psnr_db, 60.0) << what << ": hw against the reference: " << hw.line();
      EXPECT_EQ(hw.pinholes + hw.wrong_object + hw.spurious, 0u) << what << ": " << hw.line();
    }
  }
}
