// The pixel trace (engines/pixel_trace.h): every primitive's pixels in one block, in
// traversal order, each equal to the pixel datapath's result along the primitive's spans,
// and the same for any thread count.
#include <gtest/gtest.h>

#include <string>

#include "hw_model/datapath/pixel_datapath.h"
#include "hw_model/engines/frame_setup.h"
#include "hw_model/engines/pixel_trace.h"
#include "modeling/loader/scene_loader.h"

using namespace qacc;

namespace {

void expectSame(const TracedPixel& a, const TracedPixel& b) {
  EXPECT_EQ(a.z, b.z);
  EXPECT_EQ(a.cap, b.cap);
  EXPECT_EQ(a.hit, b.hit);
  EXPECT_EQ(a.candidate, b.candidate);
}

}  // namespace

TEST(PixelTrace, OneBlockInTraversalOrder) {
  Scene scene = loadScene(std::string(QACC_SOURCE_DIR) + "/scenes/sphereflake.json");
  scene.width = 160;
  scene.height = 120;
  const HwConfig cfg;
  const FrameSetup fs = FrameSetup::build(scene, cfg, 2);
  const PixelTrace tr = PixelTrace::build(fs.setups, cfg, 2);
  const std::size_t n = fs.setups.size();
  ASSERT_EQ(tr.first.size(), n + 1);
  ASSERT_EQ(tr.rows.size(), n);
  EXPECT_EQ(tr.first.front(), 0u);
  EXPECT_EQ(tr.first.back(), tr.pixels.size());
  std::size_t visible = 0;
  for (std::size_t i = 0; i < n; ++i) {
    const PrimitiveSetup& s = fs.setups[i];
    ASSERT_LE(tr.first[i], tr.first[i + 1]);
    if (!s.visible) {
      EXPECT_EQ(tr.first[i], tr.first[i + 1]) << "primitive " << i;
      continue;
    }
    ++visible;
    // The datapath again along the traced spans: the k-th issued pixel is the k-th result.
    OverflowCounters ovf;
    PixelDatapath pp(s, cfg);
    int k = 0;
    for (const RowSpans& r : tr.rows[i])
      for (int j = 0; j < r.n; ++j) {
        pp.startSpan(r.s[j].x0 - s.x0, r.y - s.y0);
        for (int x = r.s[j].x0; x < r.s[j].x1; ++x, ++k) {
          const PixelOutcome o = pp.evaluate(ovf);
          pp.stepRight();
          TracedPixel t;
          t.z = std::int64_t(o.z);
          t.cap = o.cap;
          t.hit = o.hit;
          t.candidate = o.candidate;
          expectSame(tr.pixel(int(i), k), t);
          EXPECT_EQ(tr.clipPasses(int(i)), o.clipPasses);
        }
      }
    EXPECT_EQ(tr.first[i] + std::size_t(k), tr.first[i + 1]) << "primitive " << i;
  }
  EXPECT_GT(visible, 10u);
  // Any thread count gives the same block.
  const PixelTrace one = PixelTrace::build(fs.setups, cfg, 1);
  ASSERT_EQ(one.pixels.size(), tr.pixels.size());
  EXPECT_EQ(one.first, tr.first);
  EXPECT_EQ(one.passes, tr.passes);
  for (std::size_t p = 0; p < tr.pixels.size(); ++p) expectSame(one.pixels[p], tr.pixels[p]);
}
