#include "hw_model/engines/item_clock.h"

#include <algorithm>
#include <optional>
#include <utility>
#include <stdexcept>
#include <string>

#include "hw_model/datapath/hierarchical_z_memory.h"
#include "hw_model/datapath/screen_interleave.h"
#include "hw_model/timing/hierarchical_z_unit.h"
#include "hw_model/timing/host_interface_unit.h"
#include "hw_model/timing/pixel_pipeline_unit.h"
#include "hw_model/timing/setup_unit.h"
#include "hw_model/timing/shading_unit.h"
#include "hw_model/timing/traversal_unit.h"
#include "hw_model/timing/zbuffer_unit.h"

namespace qacc {

bool itemClockApplies(const HwConfig& cfg) {
  return cfg.pipelines >= 1 && cfg.pipelines <= 64 && cfg.zbuffer_banks % cfg.pipelines == 0;
}

namespace {

constexpr std::uint64_t kNone = ~std::uint64_t(0);

// What a unit's tick did in each cycle, for the cycles not yet counted: changed anything,
// waited on an output (a full channel, a busy bank), holds work after the tick. A bit a cycle
// for each, in rings of 64-bit words over the cycles from the first one not counted, grown
// when an event lies further ahead (events can lie far ahead of the traversal when a unit
// downstream is slower than the pipelines: a bit a cycle keeps that memory near the ticked
// machine's, which holds the waiting pixels themselves).
class CycleFlags {
 public:
  enum Flag { kChanged = 0, kStalled = 1, kHolding = 2 };
  CycleFlags() : ring_(3 * kInitialWords, 0), bits_(ring_.data()), mask_(kInitialWords - 1) {}
  CycleFlags(const CycleFlags&) = delete;
  CycleFlags& operator=(const CycleFlags&) = delete;
  CycleFlags(CycleFlags&& o) noexcept { *this = std::move(o); }
  CycleFlags& operator=(CycleFlags&& o) noexcept {
    ring_ = std::move(o.ring_);
    bits_ = ring_.data();
    mask_ = o.mask_;
    base_ = o.base_;
    baseWord_ = o.baseWord_;
    end_ = o.end_;
    return *this;
  }
  // The unit's marks so far end at cycle t (the last event of an item: its exit, which
  // follows every other mark of that item; once an item, not once a mark, which would chain
  // every mark through this one value).
  void lastMark(std::uint64_t t) { end_ = std::max(end_, t + 1); }
  template <Flag F>
  void mark(std::uint64_t t) {
    reach(t);
    bits_[word(t >> 6) + F] |= std::uint64_t(1) << (t & 63);
  }
  template <Flag F>
  void markRange(std::uint64_t a, std::uint64_t b) {
    if (a >= b) return;
    reach(b - 1);
    words(a, b, [&](std::size_t w, std::uint64_t m) { bits_[w + F] |= m; });
  }
  // Counts the cycles before t as the unit's tick counts them (Unit::countCycle: changed →
  // busy, else waited → stall, else holding → busy, else idle), and forgets them. Cycles
  // after the last one marked are idle: nothing to count.
  void count(std::uint64_t t, UnitStats& u) {
    const std::uint64_t stop = std::min(t, end_);
    if (base_ < stop) {
      words(base_, stop, [&](std::size_t w, std::uint64_t m) {
        std::uint64_t* r = bits_ + w;
        const std::uint64_t c = r[kChanged] & m, st = r[kStalled] & m, h = r[kHolding] & m;
        u.busy += bitsSet(c | (h & ~st));
        u.stall += bitsSet(st & ~c);
        for (int f = 0; f < 3; ++f) r[f] &= ~m;
      });
    }
    base_ = std::max(base_, t);
    baseWord_ = base_ >> 6;
  }

 private:
  static constexpr std::size_t kInitialWords = 64;  // a power of two
  // The bits set in x, inline (the host's baseline instruction set has no popcount
  // instruction: __builtin_popcountll would be a call).
  static std::uint64_t bitsSet(std::uint64_t x) {
    x -= (x >> 1) & 0x5555555555555555ull;
    x = (x & 0x3333333333333333ull) + ((x >> 2) & 0x3333333333333333ull);
    x = (x + (x >> 4)) & 0x0f0f0f0f0f0f0f0full;
    return (x * 0x0101010101010101ull) >> 56;
  }
  // The ring's first word of cycle word w (the three flags' words side by side).
  std::size_t word(std::uint64_t w) const { return std::size_t(w & mask_) * 3; }
  // Calls f(ring word, mask of the cycles of [a, b) in it) for each word [a, b) touches.
  template <typename F>
  void words(std::uint64_t a, std::uint64_t b, F&& f) {
    const std::uint64_t last = (b - 1) >> 6;
    for (std::uint64_t w = a >> 6; w <= last; ++w) {
      std::uint64_t m = ~std::uint64_t(0);
      if (w == a >> 6) m &= ~std::uint64_t(0) << (a & 63);
      if (w == last) m &= ~std::uint64_t(0) >> (63 - ((b - 1) & 63));
      f(word(w), m);
    }
  }
  void reach(std::uint64_t t) {
    if ((t >> 6) - baseWord_ > mask_) grow(t);  // also t < base_ (the difference wraps)
  }
  [[gnu::noinline]] void grow(std::uint64_t t) {
    if (t < base_) throw std::logic_error("item clock: an event before the cycles already counted");
    const std::uint64_t first = baseWord_, need = (t >> 6) - first + 1;
    std::size_t n = mask_ + 1;
    while (n < need) n *= 2;
    std::vector<std::uint64_t> bigger(3 * n, 0);
    for (std::uint64_t w = first; w <= first + mask_; ++w)
      for (std::size_t f = 0; f < 3; ++f) bigger[std::size_t(w & (n - 1)) * 3 + f] = ring_[word(w) + f];
    ring_.swap(bigger);
    bits_ = ring_.data();
    mask_ = n - 1;
  }
  std::vector<std::uint64_t> ring_;  // per word of 64 cycles: changed, stalled, holding
  std::uint64_t* bits_;              // ring_.data()
  std::uint64_t mask_;               // words of 64 cycles in the ring - 1
  std::uint64_t base_ = 0;           // the first cycle not counted
  std::uint64_t baseWord_ = 0;       // base_ / 64
  std::uint64_t end_ = 0;            // one past the last cycle marked (lastMark)
};

// A unit's cycles holding work, as the union of its items' [entry, exit) intervals, which
// arrive with non-decreasing ends: one open interval, marked when the next one is disjoint.
class HoldingCycles {
 public:
  void add(CycleFlags& f, std::uint64_t a, std::uint64_t b) {
    if (a <= b_ && a_ < b_) {
      b_ = std::max(b_, b);
      return;
    }
    f.markRange<CycleFlags::kHolding>(a_, b_);
    a_ = a;
    b_ = b;
  }
  // Marks the part before t (before the flags count it).
  void markBefore(CycleFlags& f, std::uint64_t t) {
    const std::uint64_t e = std::min(b_, t);
    if (a_ < e) {
      f.markRange<CycleFlags::kHolding>(a_, e);
      a_ = e;
    }
  }

 private:
  std::uint64_t a_ = 0, b_ = 0;
};

// The cycles of the last `capacity` items through a channel (when each was received): the
// item `capacity` places ahead of the next one is the one whose receive frees its slot.
class Window {
 public:
  // Capacity 0: an unbounded channel (one slot that stays 0: no constraint).
  explicit Window(std::size_t capacity)
      : times_(std::max<std::size_t>(capacity, 1), 0), keep_(capacity == 0 ? 0 : ~std::uint64_t(0)) {}
  // The first cycle the next item can be sent in.
  std::uint64_t sendFrom() const { return times_[i_]; }
  void push(std::uint64_t received) {
    times_[i_] = (received + 1) & keep_;  // the slot is free from the cycle after the receive
    if (++i_ == times_.size()) i_ = 0;
  }

 private:
  std::vector<std::uint64_t> times_;  // per slot: its last receive + 1 (0: never used)
  std::uint64_t keep_;
  std::size_t i_ = 0;
};

// One pipeline's path: its pixel pipeline, its Z port, its shading unit.
struct Lane {
  explicit Lane(std::size_t capacity) : toPipeline(capacity), toZ(capacity), toShading(capacity) {}
  Window toPipeline, toZ, toShading;  // the receive cycles of each channel's last items
  // Pixel pipeline.
  std::uint64_t nextAccept = 0, lastRetire = 0;
  CycleFlags pipeFlags;
  HoldingCycles pipeHolding;
  UnitStats pipe;
  // Z port.
  std::uint64_t zNextIssue = 0, zLastRetire = 0;
  HoldingCycles zHolding;
  // Shading unit.
  std::uint64_t shadeNextAccept = 0, shadeLastDone = 0;
  CycleFlags shadeFlags;
  HoldingCycles shadeHolding;
  UnitStats shade;
};

// The hierarchical Z unit (HierarchicalZUnit's rules): its tile memory, the Z unit's writes
// on their way to it, its counters. The writes reach the tile memory by due cycle (issue +
// update_latency) and, within one issue cycle, in the Z unit's round-robin order of that
// cycle (port rr, rr + 1, ..., with rr = cycle mod P: the pointer advances every cycle from
// 0). The order matters: a write that completes a tile's layer and one that joins the next
// leave another tile record the other way round. Each port issues in order, so each port's
// writes wait in a queue of their own, in due order, and a lookup merges the queues' heads.
class HierarchicalZ {
 public:
  HierarchicalZ(const HwConfig& cfg, const std::vector<PrimitiveSetup>& setups, int width, int height)
      : p_(HierarchicalZUnit::Params::from(cfg)), memory_(cfg, 0, 0, width, height), queues_(std::size_t(cfg.pipelines)) {
    floors_.reserve(setups.size());
    for (const PrimitiveSetup& s : setups) floors_.push_back(ZBufferMemory::storedValue(s.zFloor, cfg));
    unit.name = "hierarchical_z";
  }
  const HierarchicalZUnit::Params& params() const { return p_; }
  // A Z write issued by `port` in cycle `issue`: due at the tile memory update_latency later,
  // a cycle in which the unit is busy (its tick writes the tile).
  void noteWrite(std::uint64_t issue, std::size_t port, int x, int y, std::uint32_t stored) {
    const std::uint64_t due = issue + std::uint64_t(p_.update_latency);
    queues_[port].writes.push_back({due, x, y, stored});
    firstDue_ = std::min(firstDue_, due);
    flags.mark<CycleFlags::kChanged>(due);
    flags.lastMark(due);
  }
  // The lookup of the block of a span starting at (x, y), for primitive `prim`, in cycle t:
  // true when rejected. It sees the writes due by t.
  bool rejects(std::uint64_t t, int prim, int x, int y) {
    if (firstDue_ <= t) applyDue(t);
    flags.mark<CycleFlags::kChanged>(t);
    flags.lastMark(t);
    ++unit.items;
    ++counters.blocks_tested;
    return memory_.rejects(memory_.tileOf(x, y), floors_[std::size_t(prim)]);
  }
  HierarchicalZCounters counters;
  CycleFlags flags;  // busy in a cycle with a lookup or a tile update
  UnitStats unit;

 private:
  struct Write {
    std::uint64_t due;
    int x, y;
    std::uint32_t stored;
  };
  // A port's writes not yet in the tile memory, in due order, from `head`.
  struct Queue {
    std::vector<Write> writes;
    std::size_t head = 0;
    bool waiting() const { return head < writes.size(); }
    const Write& front() const { return writes[head]; }
    void pop() {  // the applied writes dropped once they are half the queue (bounded memory)
      if (++head >= 256 && 2 * head >= writes.size()) {
        writes.erase(writes.begin(), writes.begin() + std::ptrdiff_t(head));
        head = 0;
      }
    }
  };
  // Writes the tile memory with every write due by t, in the order they reach it.
  [[gnu::noinline]] void applyDue(std::uint64_t t) {
    const std::size_t P = queues_.size();
    for (;;) {
      // The first write to reach the tile memory: the earliest due; at equal dues (one issue
      // cycle) the first port in that cycle's round-robin order, from (due - latency) mod P.
      std::size_t best = P;
      std::uint64_t bestDue = kNone, bestRank = 0;
      for (std::size_t p = 0; p < P; ++p) {
        if (!queues_[p].waiting()) continue;
        const std::uint64_t due = queues_[p].front().due;
        if (due > bestDue || due > t) continue;
        const std::uint64_t issue = due - std::uint64_t(p_.update_latency);
        const std::uint64_t rank = (p + P - issue % P) % P;
        if (due < bestDue || rank < bestRank) {
          best = p;
          bestDue = due;
          bestRank = rank;
        }
      }
      if (best == P) break;
      const Write& w = queues_[best].front();
      memory_.write(w.x, w.y, w.stored);
      queues_[best].pop();
    }
    firstDue_ = kNone;
    for (const Queue& q : queues_)
      if (q.waiting()) firstDue_ = std::min(firstDue_, q.front().due);
  }
  HierarchicalZUnit::Params p_;
  HierarchicalZMemory memory_;
  std::vector<Queue> queues_;          // per Z port
  std::uint64_t firstDue_ = kNone;     // the earliest due of the queues' writes
  std::vector<std::uint32_t> floors_;  // each primitive's depth floor, stored (ZBufferMemory::storedValue)
};

// runItemClock with the hierarchical Z unit (H) or without: one instantiation each, so that
// the loop without it carries none of its code.
template <bool H>
ItemClockRun runItems(const HwConfig& cfg, const std::vector<PrimitiveSetup>& setups, const PixelTrace& trace,
                      ZBufferMemory& zb, PixelCounters& px) {
  const HostInterfaceUnit::Params hostP = HostInterfaceUnit::Params::from(cfg);
  const SetupUnit::Params setupP = SetupUnit::Params::from(cfg);
  const TraversalUnit::Params travP = TraversalUnit::Params::from(cfg);
  const std::uint64_t pipeLatency = std::uint64_t(PixelPipelineUnit::Params::from(cfg).latency);
  const ZBufferUnit::Params zP = ZBufferUnit::Params::from(cfg);
  const ShadingUnit::Params shadeP = ShadingUnit::Params::from(cfg);
  const ZBufferMemory::StoredFormat stored = ZBufferMemory::StoredFormat::from(cfg);
  const std::size_t P = std::size_t(cfg.pipelines);

  ItemClockRun run;
  UnitStats host, setup, traversal, zunit;
  host.name = "host_interface";
  setup.name = "setup";
  traversal.name = "traversal";
  zunit.name = "zbuffer";
  std::vector<Lane> lanes;
  lanes.reserve(P);
  for (std::size_t p = 0; p < P; ++p) {
    lanes.emplace_back(std::size_t(cfg.pixel_fifo_depth));
    lanes[p].pipe.name = "pixel_pipeline_" + std::to_string(p);
    lanes[p].shade.name = "shading_" + std::to_string(p);
  }
  CycleFlags zFlags;
  std::optional<HierarchicalZ> hizUnit;
  if constexpr (H) hizUnit.emplace(cfg, setups, zb.width, zb.height);
  HierarchicalZ* const hiz = hizUnit ? &*hizUnit : nullptr;
  std::vector<std::uint64_t> bankFree(std::size_t(zP.banks), 0);
  // The last cycle in which anything changed (0 also when nothing ever does: the ticked
  // machine then runs one idle cycle); each lane's last events are its last retires.
  std::uint64_t last = 0;
  const auto changedAt = [&](std::uint64_t t) { last = std::max(last, t); };
  // Every flag before cycle t is final (each event of a pixel lies after the cycle it was
  // issued in): count those cycles.
  const auto countBefore = [&](std::uint64_t t) {
    for (Lane& l : lanes) {
      l.pipeHolding.markBefore(l.pipeFlags, t);
      l.pipeFlags.count(t, l.pipe);
      l.zHolding.markBefore(zFlags, t);
      l.shadeHolding.markBefore(l.shadeFlags, t);
      l.shadeFlags.count(t, l.shade);
    }
    zFlags.count(t, zunit);
    if constexpr (H) hiz->flags.count(t, hiz->unit);
  };
  std::uint64_t counted = 0;  // the cycles counted so far

  // One pixel issued in cycle s to lane p: its pipeline, Z port and shading unit.
  const auto pixel = [&](std::uint64_t s, std::size_t p, int prim, int x, int y, const TracedPixel& o,
                         int passes) __attribute__((always_inline)) {
    Lane& l = lanes[p];
    // Pixel pipeline: accepted once arrived (s + 1) and its stages take it.
    const std::uint64_t r = std::max(s + 1, l.nextAccept);
    l.nextAccept = r + std::uint64_t(std::max(1, passes));
    l.toPipeline.push(r);
    ++l.pipe.items;
    ++px.tested;
    px.clip_passes += std::uint64_t(passes);
    if (o.hit) {
      ++px.covered;
      px.caps += o.cap >= 0;
    } else {
      px.clipped += o.candidate != 0;
    }
    l.pipeFlags.mark<CycleFlags::kChanged>(r);
    // It leaves in order once done; a visible point waits for room on the Z port's channel.
    const std::uint64_t head = std::max(r + pipeLatency, l.lastRetire);
    std::uint64_t q = head;
    if (o.hit) {
      q = std::max(head, l.toZ.sendFrom());
      l.pipeFlags.markRange<CycleFlags::kStalled>(head, q);
    }
    l.lastRetire = q;
    l.pipeFlags.mark<CycleFlags::kChanged>(q);
    l.pipeFlags.lastMark(q);
    l.pipeHolding.add(l.pipeFlags, r, q);
    if (!o.hit) return;
    // Z port: the request arrives at q + 1, after the port's previous one, and waits for its bank.
    const std::uint64_t ready = std::max(q + 1, l.zNextIssue);
    std::uint64_t& bank = bankFree[std::size_t(ZBufferMemory::bankOf(x, y, zP.banks))];
    const std::uint64_t issue = std::max(ready, bank);
    zFlags.markRange<CycleFlags::kStalled>(ready, issue);
    bank = issue + std::uint64_t(zP.bank_busy);
    l.zNextIssue = issue + 1;
    l.toZ.push(issue);
    ++zunit.items;
    zFlags.mark<CycleFlags::kChanged>(issue);
    const std::int64_t z = std::int64_t(o.z);
    const std::uint32_t value = stored(z);
    const bool pass = zb.testAndWrite(zb.index(x, y), value, prim, z, int(o.cap));
    if constexpr (H)
      if (pass) hiz->noteWrite(issue, p, x, y, value);
    if (pass) ++px.written;
    else ++px.depth_rejected;
    // The read leaves in order after its latency; a pass waits for room on the shading channel.
    const std::uint64_t zHead = std::max(issue + std::uint64_t(zP.read_latency), l.zLastRetire);
    std::uint64_t zq = zHead;
    if (pass) {
      zq = std::max(zHead, l.toShading.sendFrom());
      zFlags.markRange<CycleFlags::kStalled>(zHead, zq);
    }
    l.zLastRetire = zq;
    zFlags.mark<CycleFlags::kChanged>(zq);
    zFlags.lastMark(zq);
    l.zHolding.add(zFlags, issue, zq);
    if (!pass) return;
    // Shading: accepted once arrived, one every cycles_per_pixel; delivered after its latency.
    const std::uint64_t g = std::max(zq + 1, l.shadeNextAccept);
    l.shadeNextAccept = g + std::uint64_t(shadeP.cycles_per_pixel);
    l.toShading.push(g);
    ++l.shade.items;
    ++run.delivered;
    const std::uint64_t done = g + std::uint64_t(shadeP.latency);
    l.shadeFlags.mark<CycleFlags::kChanged>(g);
    l.shadeFlags.mark<CycleFlags::kChanged>(done);
    l.shadeFlags.lastMark(done);
    l.shadeHolding.add(l.shadeFlags, g, done);
    l.shadeLastDone = done;
  };

  // Traversal of one primitive's rows from cycle t: returns the cycle after its last. With
  // the hierarchical Z unit (H), the first pixel of each block of a span (its pixels in one
  // tile) is looked up first, in the cycle traversal reaches it (before it waits for a
  // pipeline): a rejected block is skipped and its lookup ends the cycle (TraversalUnit).
  const auto traverse = [&](int prim, const std::vector<RowSpans>& rows, const TracedPixel* pixels,
                            int passes, std::uint64_t t) __attribute__((always_inline)) {
    const int tileMask = H ? hiz->params().tile_size - 1 : 0;  // tiles are a power of two wide (HwConfig)
    bool tested = false, accepted = false;
    int k = 0;
    const RowSpans* const rowEnd = rows.data() + rows.size();
    for (const RowSpans* rp = rows.data(); rp != rowEnd; ++rp) {
      const RowSpans& row = *rp;
      if (t - counted >= 4096) {  // every 4096 cycles or more, at a row's start
        countBefore(t);
        counted = t;
      }
      // The Z-buffer records of the row after next, asked of the memory now: a frame's
      // records (33 MB at 1920x1080) are far from the caches, and a row's first ones missed
      // them (a fifth of the loop's time in molecule's profile).
      if (rowEnd - rp > 2) {
        const RowSpans& ahead = rp[2];
        for (int sp = 0; sp < ahead.n; ++sp) {
          const ZEntry* e = &zb.px[zb.index(ahead.s[sp].x0, ahead.y)];
          const int n = std::min(ahead.s[sp].x1 - ahead.s[sp].x0, 32);
          for (int i = 0; i < n; i += 4) __builtin_prefetch(e + i);
        }
      }
      // A row starts on a new cycle; up to one pixel a pipeline a cycle, in span order,
      // stopping at the first pipeline whose channel is full.
      std::uint64_t used = 0;
      for (int sp = 0; sp < row.n; ++sp) {
        const int x1 = row.s[sp].x1;
        int x = row.s[sp].x0;
        do {
          if constexpr (H) {
            if (x == row.s[sp].x0 || (x & tileMask) == 0) {  // a block begins: its lookup
              tested = true;
              if (hiz->rejects(t, prim, x, row.y)) {
                const int end = std::min(x1, (x | tileMask) + 1);  // the tile's end (x >= 0)
                hiz->counters.blockRejected(end - x, int(P), hiz->params().lookup_cycles);
                k += end - x;
                x = end;
                ++traversal.busy;
                changedAt(t);
                ++t;
                used = 0;
                continue;
              }
              accepted = true;
            }
          }
          const int p = travP.pipelineOf(x, row.y);
          const std::uint64_t bit = std::uint64_t(1) << p;
          if (used & bit) {  // a new cycle
            ++traversal.busy;
            ++t;
            used = 0;
          }
          const std::uint64_t from = lanes[std::size_t(p)].toPipeline.sendFrom();
          if (from > t) {  // full: the cycle ends; traversal waits until the slot is freed
            if (used) {
              ++traversal.busy;
              ++t;
              used = 0;
            }
            if (from > t) {
              traversal.stall += from - t;
              t = from;
            }
          }
          used |= bit;
          pixel(t, std::size_t(p), prim, x, row.y, pixels[k++], passes);
          ++x;
        } while (x < x1);
      }
      // The row's last cycle (unless a rejected block's lookup ended it).
      if (!H || used) {
        ++traversal.busy;
        changedAt(t);
        ++t;
      }
    }
    if constexpr (H) hiz->counters.primitiveDone(tested, accepted);
    return t;
  };

  // Host interface, setup and traversal, primitive by primitive.
  Window hostToSetup(std::size_t(cfg.host_fifo_depth)), setupToTraversal(std::size_t(cfg.setup_fifo_depth));
  std::uint64_t hostNext = 0;   // the cycle the host starts its next descriptor
  std::uint64_t setupFree = 0;  // the cycle the setup unit can take its next one (the last hand-on)
  std::uint64_t travFree = 0;   // the cycle traversal can take its next primitive
  for (std::size_t j = 0; j < setups.size(); ++j) {
    const PrimitiveSetup& s = setups[j];
    // Host: the descriptor's transfer, then the send once the setup channel has room.
    const std::uint64_t transfer = std::uint64_t(hostP.transferCycles(s.descriptorWords));
    const std::uint64_t hostReady = hostNext + transfer - 1;
    const std::uint64_t sent = std::max(hostReady, hostToSetup.sendFrom());
    host.busy += transfer;
    host.stall += sent - hostReady;
    ++host.items;
    changedAt(sent);
    hostNext = sent + 1;
    // Setup: takes it once arrived and free, holds it for its operations, then hands it on
    // (or drops a primitive culled at the host).
    const std::uint64_t took = std::max(sent + 1, setupFree);
    hostToSetup.push(took);
    if (j > 0 && took == setupFree) --setup.busy;  // the previous hand-on's cycle took this one too
    const std::uint64_t ops = std::uint64_t(setupP.cycles(s));
    const std::uint64_t setupReady = took + ops;
    ++setup.items;
    setup.busy += ops + 1;  // its cycles, and the cycle it hands on or drops the primitive
    std::uint64_t out = setupReady;
    if (!s.culled) out = std::max(setupReady, setupToTraversal.sendFrom());
    setup.stall += out - setupReady;
    setupFree = out;
    changedAt(out);
    if (s.culled) {
      ++run.culled;
      continue;
    }
    // Traversal: takes it once arrived and free; its first pixels leave the next cycle.
    const std::uint64_t recv = std::max(out + 1, travFree);
    setupToTraversal.push(recv);
    ++traversal.items;
    ++traversal.busy;
    changedAt(recv);
    travFree = recv + 1;
    if (!s.visible) continue;
    const int prim = int(j);
    trace.awaitPrimitive(prim);
    const std::vector<RowSpans>& rows = trace.rows[j];
    if (rows.empty()) continue;
    const int passes = trace.clipPasses(prim);
    const TracedPixel* const pixels = &trace.pixel(prim, 0);
    travFree = traverse(prim, rows, pixels, passes, recv + 1);
  }

  // The frame ends after the last cycle in which anything changed.
  for (const Lane& l : lanes) last = std::max({last, l.lastRetire, l.zLastRetire, l.shadeLastDone});
  run.cycles = last + 1;
  for (Lane& l : lanes) {
    l.pipeHolding.add(l.pipeFlags, kNone, kNone);
    l.zHolding.add(zFlags, kNone, kNone);
    l.shadeHolding.add(l.shadeFlags, kNone, kNone);
  }
  countBefore(run.cycles);
  const auto finish = [&](UnitStats& u) {
    if (u.busy + u.stall > run.cycles) throw std::logic_error("item clock: " + u.name + " counted past the frame");
    u.idle = run.cycles - u.busy - u.stall;
    run.units.push_back(u);
  };
  finish(host);
  finish(setup);
  finish(traversal);
  for (Lane& l : lanes) finish(l.pipe);
  finish(zunit);
  if constexpr (H) {
    finish(hiz->unit);
    run.hiz = hiz->counters;
    run.hiz.enabled = true;
  }
  for (Lane& l : lanes) finish(l.shade);
  return run;
}

}  // namespace

ItemClockRun runItemClock(const HwConfig& cfg, const std::vector<PrimitiveSetup>& setups, const PixelTrace& trace,
                          ZBufferMemory& zb, PixelCounters& px) {
  if (!itemClockApplies(cfg)) throw std::logic_error("item clock: not for this configuration");
  return cfg.hierarchical_z ? runItems<true>(cfg, setups, trace, zb, px) : runItems<false>(cfg, setups, trace, zb, px);
}

}  // namespace qacc
