// The pixel trace (engines/pixel_trace.h): every primitive's pixels in one block, in
// traversal order, each equal to the pixel datapath's result along the primitive's spans,
// and the same for any thread count.
#include <gtest/gtest.h>

#include <string>
#include <thread>

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

// The setups of a shipped scene at w x h, default configuration.
FrameSetup setupsOf(const std::string& name, int w, int h) {
  Scene scene = loadScene(std::string(QACC_SOURCE_DIR) + "/scenes/" + name + ".json");
  scene.width = w;
  scene.height = h;
  return FrameSetup::build(scene, HwConfig(), 2);
}

}  // namespace

TEST(PixelTrace, OneBlockInTraversalOrder) {
  const HwConfig cfg;
  const FrameSetup fs = setupsOf("sphereflake", 160, 120);
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

// Filled ahead: threads fill the planned trace while a reader takes the primitives in order,
// waiting for each (awaitPrimitive) as the traversal unit does, and filling those no thread
// has taken yet (all of them with no filler); the trace it reads is the whole trace, and the
// same as build's.
TEST(PixelTrace, FilledAheadWhileReadEqualsTheWholeTrace) {
  const HwConfig cfg;
  const FrameSetup fs = setupsOf("molecule", 320, 240);
  const PixelTrace whole = PixelTrace::build(fs.setups, cfg, 1);
  for (int fillers : {0, 1, 3}) {
    PixelTrace tr = PixelTrace::plan(fs.setups, cfg, 2);
    EXPECT_EQ(tr.first, whole.first);
    std::vector<std::thread> threads;
    for (int t = 0; t < fillers; ++t) threads.emplace_back([&] { tr.fillAhead(); });
    std::size_t compared = 0;
    for (std::size_t i = 0; i < fs.setups.size(); ++i) {
      tr.awaitPrimitive(int(i));
      EXPECT_EQ(tr.clipPasses(int(i)), whole.clipPasses(int(i))) << "primitive " << i;
      for (std::size_t p = whole.first[i]; p < whole.first[i + 1]; ++p, ++compared) expectSame(tr.pixels[p], whole.pixels[p]);
    }
    for (std::thread& t : threads) t.join();
    tr.finishFill();
    EXPECT_EQ(compared, whole.pixels.size());
    EXPECT_GT(compared, 10000u);
    EXPECT_EQ(tr.overflow.total(), whole.overflow.total());
    EXPECT_GE(tr.waitSeconds(), 0.0);
  }
}
