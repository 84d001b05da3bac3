// Channels, pipelines and the registry of the cycle engine (hw_model/timing/): two-phase
// commit, latency, capacity and back-pressure; the loop over the units (engines/machine_run.h).
#include <gtest/gtest.h>

#include <random>
#include <vector>

#include "hw_model/config/hw_config.h"
#include "hw_model/engines/machine_run.h"
#include "hw_model/timing/channel_registry.h"
#include "hw_model/timing/pipeline.h"
#include "hw_model/timing/shading_unit.h"
#include "hw_model/timing/traversal_unit.h"
#include "hw_model/timing/zbuffer_unit.h"

using namespace qacc;

TEST(Channel, AnItemSentInACycleIsSeenOnlyFromTheNextWhateverTheTickOrder) {
  ChannelRegistry wires;
  Channel<int>& c = wires.make<int>(4);
  c.send(7);
  EXPECT_FALSE(c.ready()) << "a receiver ticking after the sender in the same cycle must not see the item";
  EXPECT_FALSE(c.idle());
  EXPECT_TRUE(wires.endCycle()) << "a send is a change";
  ASSERT_TRUE(c.ready());
  EXPECT_EQ(c.front(), 7);
  c.receive();
  EXPECT_TRUE(wires.endCycle()) << "a receive is a change";
  EXPECT_FALSE(wires.endCycle()) << "a cycle with no traffic is not";
  EXPECT_TRUE(wires.idle());
}

TEST(Channel, CarriesItsLatencyAndKeepsOrder) {
  ChannelRegistry wires;
  Channel<int>& c = wires.make<int>(0);
  c.send(1, 3);  // sent in cycle 0, arrives in cycle 3
  wires.endCycle();
  c.send(2, 3);  // sent in cycle 1, arrives in cycle 4
  EXPECT_EQ(c.nextArrival(), 3u);
  wires.endCycle();
  EXPECT_FALSE(c.ready()) << "cycle 2";
  wires.endCycle();
  ASSERT_TRUE(c.ready()) << "cycle 3";
  EXPECT_EQ(c.front(), 1);
  c.receive();
  EXPECT_FALSE(c.ready()) << "the second item is still on the wire in cycle 3";
  EXPECT_EQ(c.nextArrival(), 4u);
  wires.endCycle();
  ASSERT_TRUE(c.ready());
  EXPECT_EQ(c.front(), 2);
}

TEST(Channel, CapacityIsCountedAtTheStartOfTheCycle) {
  ChannelRegistry wires;
  Channel<int>& c = wires.make<int>(2);
  ASSERT_TRUE(c.canSend());
  c.send(1);
  ASSERT_TRUE(c.canSend());
  c.send(2);
  EXPECT_FALSE(c.canSend()) << "two items sent this cycle fill a channel of two";
  wires.endCycle();
  EXPECT_FALSE(c.canSend()) << "full at the start of the cycle";
  c.receive();
  EXPECT_FALSE(c.canSend()) << "a slot freed by a receive is free only from the next cycle";
  wires.endCycle();
  EXPECT_TRUE(c.canSend());
  c.send(3);
  EXPECT_FALSE(c.canSend());
}

TEST(Channel, OccupancyCarriesOverCyclesWithoutTrafficAndAFastForward) {
  // A channel keeps its two-phase state itself: after cycles in which nobody touched it (and
  // a jump of the clock), the occupancy at the start of the cycle is what it held.
  ChannelRegistry wires;
  Channel<int>& c = wires.make<int>(2);
  Channel<int>& other = wires.make<int>(2);
  c.send(1);
  c.send(2);
  wires.endCycle();
  other.send(9);  // traffic elsewhere does not change c's counts
  EXPECT_TRUE(wires.endCycle());
  EXPECT_FALSE(wires.endCycle());
  wires.skipTo(50);
  EXPECT_FALSE(c.canSend()) << "still full in cycle 50";
  c.receive();
  EXPECT_FALSE(c.canSend()) << "the slot freed in cycle 50 is free from cycle 51";
  EXPECT_TRUE(wires.endCycle());
  wires.skipTo(60);
  EXPECT_TRUE(c.canSend());
  c.send(3);
  EXPECT_FALSE(c.canSend()) << "one held and one sent fill a channel of two";
}

TEST(Channel, BackPressureStallsAProducerAndLosesNothing) {
  // A producer sends one item per cycle into a channel of 2; the consumer takes one every
  // third cycle. Every item arrives once, in order, and the producer waits when it is full.
  ChannelRegistry wires;
  Channel<int>& c = wires.make<int>(2);
  int next = 0, expected = 0, stalls = 0;
  for (int cycle = 0; cycle < 300; ++cycle) {
    if (c.ready() && cycle % 3 == 0) {
      ASSERT_EQ(c.front(), expected++);
      c.receive();
    }
    if (next < 60) {
      if (c.canSend()) c.send(next++);
      else ++stalls;
    }
    ASSERT_LE(c.size(), c.capacity());
    wires.endCycle();
  }
  EXPECT_EQ(expected, 60);
  EXPECT_GT(stalls, 60);
}

TEST(Pipeline, AcceptsAtItsIntervalAndDeliversAfterItsLatency) {
  ChannelRegistry wires;
  Pipeline<int> p(wires, 5);
  std::vector<std::pair<int, std::uint64_t>> out;  // item, cycle it finished
  int next = 0;
  for (int cycle = 0; cycle < 40; ++cycle) {
    while (p.done()) {
      out.push_back({p.front(), wires.now()});
      p.retire();
    }
    if (next < 4 && p.canAccept()) {
      const std::uint64_t interval = next == 1 ? 3 : 1;  // item 1 holds the input for 3 cycles
      p.accept(next++, interval);
    }
    wires.endCycle();
  }
  ASSERT_EQ(out.size(), 4u);
  // Accepted in cycles 0, 1, 4, 5 (item 1 has an interval of 3): done 5 cycles later.
  EXPECT_EQ(out[0], (std::pair<int, std::uint64_t>{0, 5}));
  EXPECT_EQ(out[1], (std::pair<int, std::uint64_t>{1, 6}));
  EXPECT_EQ(out[2], (std::pair<int, std::uint64_t>{2, 9}));
  EXPECT_EQ(out[3], (std::pair<int, std::uint64_t>{3, 10}));
  EXPECT_FALSE(p.holdsWork());
}

TEST(Pipeline, NextEventIsTheOldestItemOrTheNextAccept) {
  ChannelRegistry wires;
  Pipeline<int> p(wires, 4);
  p.accept(1, 2);
  EXPECT_EQ(p.nextEvent(false), 4u);
  EXPECT_EQ(p.nextEvent(true), 2u);
  wires.skipTo(4);
  EXPECT_TRUE(p.done());
}

TEST(MachineRun, AUnitsPipelineKeepsTheFrameGoingUntilItsLastItemLeaves) {
  // A unit's stages are not a wire: the loop learns of them only from the unit (a change
  // when an item enters or leaves, work while one is inside). One pixel for a shading unit
  // of latency 12, on the wire in cycle 0: taken in cycle 1, done in cycle 13, and the
  // quiet cycles between are fast-forwarded, not the end of the frame: cycle 2 ticked and
  // found quiet, cycles 3 to 12 counted from cycle 3's tick.
  ChannelRegistry wires;
  Channel<PointToken>& in = wires.make<PointToken>(8);
  in.send({0, 1, 2, -1, 100});
  ShadingUnit::Params p;
  p.latency = 12;
  ShadingUnit shading("shading", p, wires, in);
  std::uint64_t fastForwarded = 0;
  const std::uint64_t cycles = runMachine(wires, fastForwarded, shading);
  EXPECT_EQ(cycles, 14u) << "cycles 0 to 13";
  EXPECT_EQ(shading.delivered(), 1u);
  EXPECT_EQ(fastForwarded, 10u) << "cycles 3 to 12";
  EXPECT_EQ(shading.stats().busy, 13u);
  EXPECT_EQ(shading.stats().idle, 1u);
}

TEST(TraversalParams, APipelineCountThatIsNotAPowerOfTwoInterleavesByTheModulo) {
  const TraversalUnit::Params three{3};
  EXPECT_EQ(three.pipelineOf(1, 2), 0);
  EXPECT_EQ(three.pipelineOf(2, 2), 1);  // (x + y) & 2 would give 0
  EXPECT_EQ(three.pipelineOf(5, 0), 2);
  const TraversalUnit::Params four{4};
  EXPECT_EQ(four.pipelineOf(5, 2), 3);
}

namespace {

// A test source: sends its points in order, point i to port i mod P, each no earlier than its
// gap after the one before, stalling while that port's channel is full.
class PointSource final : public Unit {
 public:
  PointSource(std::vector<PointToken> points, std::vector<std::uint64_t> gaps, std::vector<Channel<PointToken>*> out)
      : Unit("source"), points_(std::move(points)), gaps_(std::move(gaps)), out_(std::move(out)) {}
  bool tick(std::uint64_t now) {
    if (next_ >= points_.size()) {
      countIdle();
      return false;
    }
    if (now < sendAt_) {
      countBusy();
      return false;
    }
    Channel<PointToken>& c = *out_[next_ % out_.size()];
    if (!c.canSend()) {
      countStall();
      return false;
    }
    c.send(points_[next_]);
    ++next_;
    if (next_ < points_.size()) sendAt_ = now + gaps_[next_];
    countItem();
    countBusy();
    return true;
  }
  bool holdsWork() const { return next_ < points_.size(); }
  std::uint64_t nextEvent() const { return next_ < points_.size() ? sendAt_ : kNoEvent; }
  std::uint64_t nextChange(std::uint64_t now) const {
    return next_ < points_.size() && sendAt_ >= now ? sendAt_ : kNoEvent;
  }

 private:
  std::vector<PointToken> points_;
  std::vector<std::uint64_t> gaps_;
  std::vector<Channel<PointToken>*> out_;
  std::size_t next_ = 0;
  std::uint64_t sendAt_ = 0;
};

struct SmallMachineRun {
  std::uint64_t cycles = 0, fastForwarded = 0, conflicts = 0, delivered = 0;
  std::vector<UnitStats> units;
  PixelCounters px;
};

// source -> P channels -> Z unit -> P channels -> P shading units, ticked with repeated
// ticks and fast-forwards (everyCycle false) or every cycle.
SmallMachineRun runSmallMachine(std::uint32_t seed, bool everyCycle) {
  std::mt19937 rng(seed);
  const auto pick = [&](int lo, int hi) { return std::uniform_int_distribution<int>(lo, hi)(rng); };
  const int P = pick(1, 3), W = 8, H = 6;
  HwConfig cfg;
  cfg.pipelines = P;
  cfg.zbuffer_banks = pick(1, 4);
  cfg.zbuffer_bank_busy = pick(1, 4);
  cfg.zbuffer_read_latency = pick(1, 4);
  const std::size_t capacity = std::size_t(pick(1, 3));
  ShadingUnit::Params sp;
  sp.cycles_per_pixel = pick(1, 6);
  sp.latency = pick(1, 15);
  std::vector<PointToken> points;
  std::vector<std::uint64_t> gaps;
  for (int i = 0, n = pick(20, 120); i < n; ++i) {
    points.push_back({i, pick(0, W - 1), pick(0, H - 1), -1, std::int64_t(pick(0, 1000))});
    gaps.push_back(pick(0, 3) == 0 ? std::uint64_t(pick(0, 40)) : 0);  // some long pauses
  }
  ChannelRegistry wires;
  std::vector<Channel<PointToken>*> toZ, toShading;
  for (int p = 0; p < P; ++p) {
    toZ.push_back(&wires.make<PointToken>(capacity));
    toShading.push_back(&wires.make<PointToken>(capacity));
  }
  ZBufferMemory zb(W, H);
  PixelCounters px;
  PointSource source(points, gaps, toZ);
  ZBufferUnit z(ZBufferUnit::Params::from(cfg), cfg, wires, zb, toZ, toShading, px);
  std::vector<ShadingUnit> shading;
  shading.reserve(std::size_t(P));
  for (int p = 0; p < P; ++p) shading.emplace_back("shading", sp, wires, *toShading[std::size_t(p)]);
  SmallMachineRun r;
  r.cycles = everyCycle ? runMachine<MachineClock::EveryCycle>(wires, r.fastForwarded, source, z, shading)
                        : runMachine(wires, r.fastForwarded, source, z, shading);
  appendUnitStats(r.units, source, z, shading);
  r.conflicts = z.conflicts();
  for (const ShadingUnit& u : shading) r.delivered += u.delivered();
  r.px = px;
  return r;
}

}  // namespace

TEST(MachineRun, AWaitThroughAFastForwardCountsItsStalls) {
  // Two requests for one bank busy 10 cycles: the first issues in cycle 1, the second waits
  // from cycle 2 to 10 (a conflict each cycle) and issues in cycle 11. The first one's
  // read and shading are done in cycle 4; from then on nothing moves until the bank frees,
  // so the clock fast-forwards, and the waiting request must count a conflict and a stall
  // in those cycles as in the ticked ones.
  for (const bool everyCycle : {false, true}) {
    ChannelRegistry wires;
    HwConfig cfg;
    cfg.pipelines = 1;
    cfg.zbuffer_banks = 1;
    cfg.zbuffer_bank_busy = 10;
    cfg.zbuffer_read_latency = 1;
    Channel<PointToken>& toZ = wires.make<PointToken>(4);
    Channel<PointToken>& toShading = wires.make<PointToken>(4);
    ZBufferMemory zb(4, 4);
    PixelCounters px;
    PointSource source({{0, 1, 1, -1, 100}, {1, 1, 1, -1, 50}}, {0, 0}, {&toZ});
    ZBufferUnit z(ZBufferUnit::Params::from(cfg), cfg, wires, zb, {&toZ}, {&toShading}, px);
    ShadingUnit::Params sp;
    sp.latency = 1;
    std::vector<ShadingUnit> shading;
    shading.emplace_back("shading", sp, wires, toShading);
    std::uint64_t fastForwarded = 0;
    const std::uint64_t cycles = everyCycle ? runMachine<MachineClock::EveryCycle>(wires, fastForwarded, source, z, shading)
                                            : runMachine(wires, fastForwarded, source, z, shading);
    const std::string clock = everyCycle ? "every cycle" : "repeating";
    EXPECT_EQ(cycles, 15u) << clock << ": the second read retires in 12, shaded in 13 and 14";
    EXPECT_EQ(z.conflicts(), 9u) << clock << ": cycles 2 to 10";
    EXPECT_EQ(z.stats().stall, 8u) << clock << ": cycles 3 to 10 (in 2 the first read retired)";
    EXPECT_EQ(z.stats().busy, 4u) << clock << ": cycles 1, 2, 11 and 12";
    EXPECT_EQ(z.stats().idle, 3u) << clock << ": cycles 0, 13 and 14";
    EXPECT_EQ(shading[0].delivered(), 2u);
    if (everyCycle) EXPECT_EQ(fastForwarded, 0u);
    else EXPECT_EQ(fastForwarded, 5u) << "cycles 6 to 10: after the quiet cycle 5, before the bank frees";
  }
}

TEST(MachineRun, RepeatedTicksCountWhatTickingEveryCycleCounts) {
  // Cycles where nothing moves are repeated from one tick: up to the next timed event (a
  // fast-forward), or, where a unit waits on a full channel, up to the first cycle any tick
  // may differ (Unit::nextChange, repeatTick). Every counter must be what ticking each of
  // them gives — cycles, busy / stall / idle / items of every unit, the Z unit's bank
  // conflicts (its round-robin pointer decides which port waits), the pixels.
  int repeatedSomewhere = 0, fastForwardedSomewhere = 0;
  for (std::uint32_t seed = 1; seed <= 300; ++seed) {
    const SmallMachineRun a = runSmallMachine(seed, false), b = runSmallMachine(seed, true);
    ASSERT_EQ(a.cycles, b.cycles) << "seed " << seed;
    EXPECT_EQ(b.fastForwarded, 0u) << "seed " << seed;
    EXPECT_EQ(a.conflicts, b.conflicts) << "seed " << seed;
    EXPECT_EQ(a.delivered, b.delivered) << "seed " << seed;
    EXPECT_EQ(a.px.written, b.px.written) << "seed " << seed;
    EXPECT_EQ(a.px.depth_rejected, b.px.depth_rejected) << "seed " << seed;
    ASSERT_EQ(a.units.size(), b.units.size());
    for (std::size_t i = 0; i < a.units.size(); ++i) {
      EXPECT_EQ(a.units[i].busy, b.units[i].busy) << "seed " << seed << ", unit " << a.units[i].name;
      EXPECT_EQ(a.units[i].stall, b.units[i].stall) << "seed " << seed << ", unit " << a.units[i].name;
      EXPECT_EQ(a.units[i].idle, b.units[i].idle) << "seed " << seed << ", unit " << a.units[i].name;
      EXPECT_EQ(a.units[i].items, b.units[i].items) << "seed " << seed << ", unit " << a.units[i].name;
    }
    repeatedSomewhere += a.units[0].stall > 20;  // the source stalled long enough to repeat ticks
    fastForwardedSomewhere += a.fastForwarded > 20;
  }
  EXPECT_GT(repeatedSomewhere, 50) << "the random machines must exercise the repeated ticks";
  EXPECT_GT(fastForwardedSomewhere, 50) << "the random machines must exercise the fast-forwards";
}
