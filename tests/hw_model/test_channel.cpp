// Channels, pipelines and the registry of the cycle engine (hw_model/timing/): two-phase
// commit, latency, capacity and back-pressure; the loop over the units (engines/machine_run.h).
#include <gtest/gtest.h>

#include <vector>

#include "hw_model/engines/machine_run.h"
#include "hw_model/timing/channel_registry.h"
#include "hw_model/timing/pipeline.h"
#include "hw_model/timing/shading_unit.h"
#include "hw_model/timing/traversal_unit.h"

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
  // quiet cycles between are fast-forwarded, not the end of the frame.
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
