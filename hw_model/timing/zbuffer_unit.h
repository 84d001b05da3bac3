// ZBufferUnit: read-compare-write of the depth of each covered pixel against a banked
// memory (datapath/zbuffer_memory.h holds the records and the comparison). Pixel (x, y)
// lives in bank (x + y) mod zbuffer_banks; a read-modify-write occupies its bank for
// zbuffer_bank_busy cycles, so a request to a busy bank waits (a bank conflict, counted as
// a stall); the result is known zbuffer_read_latency cycles after issue. Up to one request
// per pipeline per cycle, round-robin priority on conflicts; each pipeline's requests stay
// in order, and a pixel always goes through the same pipeline, so the Z test sees every
// pixel's primitives in scene order. Pixels that pass go to that pipeline's shading unit.
#pragma once
#include <vector>

#include "hw_model/config/hw_config.h"
#include "hw_model/datapath/zbuffer_memory.h"
#include "hw_model/timing/channel.h"
#include "hw_model/timing/hierarchical_z_unit.h"
#include "hw_model/timing/pipeline.h"
#include "hw_model/timing/tokens.h"
#include "hw_model/timing/unit.h"

namespace qacc {

class ZBufferUnit final : public Unit {
 public:
  struct Params {
    int banks = 4;
    int read_latency = 2;  // cycles from request to data
    int bank_busy = 2;     // cycles a bank is occupied by one read-modify-write
    static Params from(const HwConfig& cfg) {
      return {cfg.zbuffer_banks, cfg.zbuffer_read_latency, cfg.zbuffer_bank_busy};
    }
  };

  ZBufferUnit(const Params& p, const HwConfig& cfg, ChannelRegistry& wires, ZBufferMemory& zb,
              std::vector<Channel<PointToken>*> in, std::vector<Channel<PointToken>*> out, PixelCounters& px);
  bool tick(std::uint64_t now);
  std::uint64_t nextEvent() const;
  // Unchanged: a read finishing, a request arriving, or a waiting request's bank freed.
  std::uint64_t nextChange(std::uint64_t now) const;
  // The bank conflicts a tick counts, and the round-robin pointer, advance with the ticks.
  TickCounts tickCounts() const {
    TickCounts c = Unit::tickCounts();
    c.extra = conflicts_;
    return c;
  }
  void repeatTick(const TickCounts& before, std::uint64_t n) {
    Unit::repeatTick(before, n);
    conflicts_ += n * (conflicts_ - before.extra);
    rr_ = (rr_ + std::size_t(n % ports_.size())) % ports_.size();
  }
  bool holdsWork() const { return inFlight_ != 0; }
  std::uint64_t conflicts() const { return conflicts_; }
  // Equal stored depths go to the primitive earlier in scene order (ZBufferMemory::
  // testAndWriteInSceneOrder): for primitives drawn after later ones (the CSG pass).
  void tiesInSceneOrder() { sceneOrderTies_ = true; }
  // Reports every write to the hierarchical Z unit's tile memory (timing/hierarchical_z_unit.h).
  void reportWritesTo(HierarchicalZUnit* hiz) { hiz_ = hiz; }

 private:
  struct InFlight {
    bool pass;
    PointToken point;
  };
  // A pipeline's port: its requests, its read pipeline, its shading unit.
  struct Port {
    Channel<PointToken>* in;
    Channel<PointToken>* out;
    Pipeline<InFlight> reads;
  };
  Params p_;
  ZBufferMemory::StoredFormat stored_;  // the stored Z format
  ZBufferMemory& zb_;
  std::vector<Port> ports_;
  PixelCounters& px_;
  int bankOf(int x, int y) const { return ZBufferMemory::bankOf(x, y, p_.banks); }
  std::vector<std::uint64_t> bankFree_;
  std::size_t inFlight_ = 0;  // requests in the read pipelines, all ports
  std::uint64_t conflicts_ = 0;
  std::size_t rr_ = 0;
  bool sceneOrderTies_ = false;
  HierarchicalZUnit* hiz_ = nullptr;
};

inline bool ZBufferUnit::tick(std::uint64_t now) {
  bool changed = false, stalled = false;
  const std::size_t P = ports_.size();
  Port* const ports = ports_.data();
  if (inFlight_ != 0) {
    for (std::size_t p = 0; p < P; ++p) {
      Pipeline<InFlight>& q = ports[p].reads;
      while (q.done()) {
        if (q.front().pass) {
          if (!ports[p].out->canSend()) {
            stalled = true;
            break;
          }
          ports[p].out->send(q.front().point);
        }
        q.retire();
        --inFlight_;
        changed = true;
      }
    }
  }
  // Issue: one request per pipeline, round-robin priority on bank conflicts.
  for (std::size_t k = 0; k < P; ++k) {
    const std::size_t p = rr_ + k < P ? rr_ + k : rr_ + k - P;
    Channel<PointToken>& in = *ports[p].in;
    if (!in.ready()) continue;
    const PointToken& r = in.front();
    std::uint64_t& bankFree = bankFree_[std::size_t(bankOf(r.x, r.y))];
    if (bankFree > now) {
      ++conflicts_;
      stalled = true;
      continue;
    }
    bankFree = now + std::uint64_t(p_.bank_busy);
    const std::size_t pix = zb_.index(r.x, r.y);
    const std::uint32_t stored = stored_(r.z);
    const bool pass = sceneOrderTies_ ? zb_.testAndWriteInSceneOrder(pix, stored, r.prim, r.z, r.cap)
                                      : zb_.testAndWrite(pix, stored, r.prim, r.z, r.cap);
    if (pass && hiz_) hiz_->noteWrite(now, r.x, r.y, stored);
    if (pass) ++px_.written;
    else ++px_.depth_rejected;
    ports[p].reads.accept({pass, r});
    ++inFlight_;
    in.receive();
    countItem();
    changed = true;
  }
  if (++rr_ == P) rr_ = 0;
  countCycle(changed, stalled, holdsWork());
  return changed;
}

}  // namespace qacc
