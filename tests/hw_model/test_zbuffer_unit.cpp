// The Z-buffer: its memory (datapath/zbuffer_memory.h: strict test, stored format, banks)
// and its timed unit (timing/zbuffer_unit.h: bank conflicts, read latency, order).
#include <gtest/gtest.h>

#include "hw_model/datapath/zbuffer_memory.h"
#include "hw_model/timing/channel_registry.h"
#include "hw_model/timing/zbuffer_unit.h"

using namespace qacc;

TEST(ZBufferMemory, StrictTestKeepsTheEarlierPrimitiveOnEqualDepth) {
  ZBufferMemory zb(4, 4);
  const std::size_t pix = zb.index(2, 1);
  EXPECT_EQ(pix, 6u);
  EXPECT_TRUE(zb.testAndWrite(pix, 100, 0, 1000, -1));
  EXPECT_FALSE(zb.testAndWrite(pix, 100, 1, 999, -1)) << "equal stored depth: the earlier primitive stays";
  EXPECT_FALSE(zb.testAndWrite(pix, 101, 2, 1001, -1));
  EXPECT_TRUE(zb.testAndWrite(pix, 99, 3, 990, 2));
  EXPECT_EQ(zb.px[pix].prim, 3);
  EXPECT_EQ(zb.px[pix].cap, 2);
  EXPECT_EQ(zb.px[pix].depth, 990);
  zb.clear();
  EXPECT_EQ(zb.px[pix].prim, -1);
}

TEST(ZBufferMemory, StoredValueIsTheTopBitsOfTheDepthFractionClamped) {
  HwConfig cfg;
  cfg.depth_frac_bits = 28;
  cfg.zbuffer_bits = 24;
  EXPECT_EQ(ZBufferMemory::storedValue(i128(0x1234567), cfg), 0x123456u);
  EXPECT_EQ(ZBufferMemory::storedValue(i128(-5), cfg), 0u) << "behind the near plane clamps to 0";
  EXPECT_EQ(ZBufferMemory::storedValue(i128(1) << 29, cfg), 0xFFFFFFu) << "beyond far clamps to the top";
  EXPECT_EQ(ZBufferMemory::bankOf(3, 2, 4), 1);
  EXPECT_EQ(ZBufferMemory::bankOf(1, 1, 2), ZBufferMemory::bankOf(0, 0, 2));
}

namespace {

// A Z-buffer unit with P = 2 ports, run for `cycles` cycles; `sends` lists (cycle, port,
// point); returns, per port, the cycles at which the points that passed reached shading.
struct ZHarness {
  HwConfig cfg;
  ChannelRegistry wires;
  ZBufferMemory zb{8, 8};
  PixelCounters px;
  std::vector<Channel<PointToken>*> in, out;
  std::unique_ptr<ZBufferUnit> unit;
  explicit ZHarness(int banks) {
    cfg.zbuffer_banks = banks;
    cfg.zbuffer_bank_busy = 2;
    cfg.zbuffer_read_latency = 2;
    for (int p = 0; p < 2; ++p) {
      in.push_back(&wires.make<PointToken>(8));
      out.push_back(&wires.make<PointToken>(8));
    }
    unit = std::make_unique<ZBufferUnit>(ZBufferUnit::Params::from(cfg), cfg, wires, zb, in, out, px);
  }
  std::vector<std::vector<std::pair<std::uint64_t, PointToken>>> run(
      const std::vector<std::tuple<std::uint64_t, int, PointToken>>& sends, int cycles) {
    std::vector<std::vector<std::pair<std::uint64_t, PointToken>>> got(2);
    for (int c = 0; c < cycles; ++c) {
      for (int p = 0; p < 2; ++p)
        while (out[std::size_t(p)]->ready()) {
          got[std::size_t(p)].push_back({wires.now(), out[std::size_t(p)]->front()});
          out[std::size_t(p)]->receive();
        }
      for (const auto& [when, port, pt] : sends)
        if (when == wires.now()) in[std::size_t(port)]->send(pt);
      unit->tick(wires.now());
      wires.endCycle();
    }
    return got;
  }
};

PointToken point(int prim, int x, int y, std::int64_t z) { return {prim, x, y, -1, z * 256}; }

}  // namespace

TEST(ZBufferUnit, RequestsToOneBankWaitForIt) {
  ZHarness h(2);
  // (0, 0) and (1, 1) both live in bank 0 of 2: one waits bank_busy cycles for the other.
  const auto got = h.run({{0, 0, point(0, 0, 0, 1000)}, {0, 1, point(1, 1, 1, 1000)}}, 20);
  ASSERT_EQ(got[0].size(), 1u);
  ASSERT_EQ(got[1].size(), 1u);
  const std::uint64_t a = got[0][0].first, b = got[1][0].first;
  // Visible in cycle 1, issued in 1 and 1 + bank_busy, read back 2 cycles later, seen one
  // cycle after that.
  EXPECT_EQ(std::min(a, b), 4u);
  EXPECT_EQ(std::max(a, b), 6u);
  EXPECT_EQ(h.unit->conflicts(), 2u) << "the loser retries in cycles 1 and 2";
  EXPECT_GT(h.unit->stats().stall + h.unit->stats().busy, 0u);
  EXPECT_EQ(h.px.written, 2u);
}

TEST(ZBufferUnit, RequestsToDifferentBanksProceedTogether) {
  ZHarness h(2);
  // (0, 0) in bank 0, (1, 0) in bank 1.
  const auto got = h.run({{0, 0, point(0, 0, 0, 1000)}, {0, 1, point(1, 1, 0, 1000)}}, 20);
  ASSERT_EQ(got[0].size(), 1u);
  ASSERT_EQ(got[1].size(), 1u);
  EXPECT_EQ(got[0][0].first, 4u);
  EXPECT_EQ(got[1][0].first, 4u);
  EXPECT_EQ(h.unit->conflicts(), 0u);
}

TEST(ZBufferUnit, APortsRequestsAreTestedInOrderAndOnlyPassingPixelsGoOn) {
  ZHarness h(4);
  // Three primitives on pixel (2, 2) through port 0, in scene order: far, near, middle.
  const auto got = h.run({{0, 0, point(0, 2, 2, 3000)}, {1, 0, point(1, 2, 2, 1000)}, {2, 0, point(2, 2, 2, 2000)}},
                         30);
  ASSERT_EQ(got[0].size(), 2u) << "the middle one fails the depth test";
  EXPECT_EQ(got[0][0].second.prim, 0);
  EXPECT_EQ(got[0][1].second.prim, 1);
  EXPECT_EQ(h.px.written, 2u);
  EXPECT_EQ(h.px.depth_rejected, 1u);
  EXPECT_EQ(h.zb.px[h.zb.index(2, 2)].prim, 1);
  EXPECT_FALSE(h.unit->holdsWork());
}

TEST(ZBufferUnit, ABankCountThatIsNotAPowerOfTwoMapsPixelsByTheModulo) {
  ZHarness h(3);
  // (1, 2) and (2, 1) live in bank (x + y) mod 3 = 0 and wait for each other; (1, 2) and
  // (0, 2) (bank 2) would not, though their sums agree in the low bits (3 and 2 AND 2).
  const auto same = h.run({{0, 0, point(0, 1, 2, 1000)}, {0, 1, point(1, 2, 1, 1000)}}, 20);
  ASSERT_EQ(same[0].size() + same[1].size(), 2u);
  EXPECT_EQ(h.unit->conflicts(), 2u);
  ZHarness g(3);
  const auto apart = g.run({{0, 0, point(0, 1, 2, 1000)}, {0, 1, point(1, 0, 2, 1000)}}, 20);
  ASSERT_EQ(apart[0].size(), 1u);
  ASSERT_EQ(apart[1].size(), 1u);
  EXPECT_EQ(apart[0][0].first, apart[1][0].first);
  EXPECT_EQ(g.unit->conflicts(), 0u);
}
