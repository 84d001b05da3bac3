// The accelerator's solid intervals (PixelDatapath::solidIntervals, the operand data of a
// CSG method) against the exact ones of the reference (raster/pixel/solid_intervals.h):
// (including a box with a spherical hole, whose f <= 0 holds on whole lines that miss the
// sphere) the same number of intervals on all but a few boundary pixels, the same bounding
// surfaces or caps, depths within the depth format's precision.
#include <gtest/gtest.h>

#include <cmath>

#include "hw_model/datapath/pixel_datapath.h"
#include "hw_model/datapath/setup_arithmetic.h"
#include "modeling/geometry/natural_quadrics.h"
#include "modeling/loader/scene_loader.h"
#include "raster/pixel/solid_intervals.h"
#include "raster/pixel/window_primitive.h"

using namespace qacc;

namespace {

struct Agreement {
  long long pixels = 0, countMismatch = 0, tagMismatch = 0, intervals = 0;
  double maxDepthError = 0;
};

Agreement compare(const std::string& objects, const std::string& eye) {
  const Scene scene = parseScene(R"({"format": "qacc-scene/1", "image": {"width": 160, "height": 120},
    "camera": {"eye": )" + eye + R"(, "target": [0, 0, 0], "fov_y_deg": 40, "near": 1, "far": 30},
    "objects": [)" + objects + "]}",
                                 "t.json", ".");
  const HwConfig cfg;
  const Eigen::Matrix4d M = scene.camera.worldToWindow(scene.width, scene.height);
  Agreement ag;
  for (int i = 0; i < int(scene.primitives.size()); ++i) {
    OverflowCounter ovf;
    const PrimitiveSetup s = setupPrimitive(scene, i, M, M.inverse(), cfg, ovf);
    if (!s.visible) continue;
    const WindowPrimitive w = toWindow(scene.primitives[std::size_t(i)], i, M, M.inverse(), scene.width, scene.height);
    PixelDatapath dp(s, cfg);
    OverflowCounters oc;
    const double unit = std::ldexp(1.0, -cfg.depth_frac_bits);
    for (int y = s.y0; y < s.y1; ++y) {
      dp.startSpan(0, y - s.y0);
      for (int x = s.x0; x < s.x1; ++x, dp.stepRight()) {
        FixedDepthInterval fx[2];
        DepthInterval ex[2];
        const int nf = dp.solidIntervals(oc, fx);
        const int ne = solidIntervals(w, x + 0.5, y + 0.5, ex);
        ++ag.pixels;
        if (nf != ne) {
          ++ag.countMismatch;
          continue;
        }
        for (int k = 0; k < nf; ++k) {
          ++ag.intervals;
          ag.tagMismatch += (fx[k].in.tag != ex[k].in.tag) + (fx[k].out.tag != ex[k].out.tag);
          ag.maxDepthError = std::max(ag.maxDepthError, std::abs(double(fx[k].in.z) * unit - ex[k].in.z));
          ag.maxDepthError = std::max(ag.maxDepthError, std::abs(double(fx[k].out.z) * unit - ex[k].out.z));
        }
      }
    }
  }
  return ag;
}

}  // namespace

TEST(CsgDatapath, SolidIntervalsAgreeWithTheReference) {
  const std::string objects = R"(
    {"type": "sphere", "center": [-1.5, 0.5, 0], "radius": 1, "solid": true, "clip": [[0.3, 1, 0.2, -0.6]]},
    {"type": "cylinder", "base": [1.5, -1, -1], "top": [1.5, 1, 1], "radius": 0.7, "solid": true},
    {"type": "cone", "apex": [0, -1.5, 1.5], "base": [0, -1.5, -0.5], "radius": 0.8, "solid": true},
    {"type": "hyperboloid1", "radii": [0.5, 0.5, 0.6], "height": 2, "solid": true, "transform": {"translate": [0, 1.5, 0]}},
    {"type": "quadric", "matrix": [[1,0,0,0],[0,0,0,0],[0,0,0,0],[0,0,0,-0.25]], "solid": true,
     "clip": [[0,1,0,-3],[0,-1,0,-3],[0,0,1,-3],[0,0,-1,-3]]},
    {"type": "quadric", "matrix": [[-1,0,0,0],[0,-1,0,0],[0,0,-1,0],[0,0,0,0.36]], "solid": true,
     "transform": {"translate": [0, 0, -1.5]},
     "clip": [[1,0,0,-0.8],[-1,0,0,-0.8],[0,1,0,-0.8],[0,-1,0,-0.8],[0,0,1,-0.8],[0,0,-1,-0.8]]})";
  for (const char* eye : {"[2, 3, 8]", "[-6, -2, 3]", "[0.3, 0.2, 9]"}) {
    const Agreement ag = compare(objects, eye);
    EXPECT_GT(ag.intervals, 5000) << eye;
    EXPECT_LE(double(ag.countMismatch), 0.005 * double(ag.pixels)) << eye << ": " << ag.countMismatch << " of " << ag.pixels;
    EXPECT_LE(double(ag.tagMismatch), 0.005 * double(ag.intervals)) << eye << ": " << ag.tagMismatch;
    EXPECT_LT(ag.maxDepthError, 1e-6) << eye;
    std::printf("eye %s: %lld pixels, %lld intervals, %lld count and %lld tag mismatches, max depth error %.3g\n",
                eye, ag.pixels, ag.intervals, ag.countMismatch, ag.tagMismatch, ag.maxDepthError);
  }
}
