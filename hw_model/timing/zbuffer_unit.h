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
#include "hw_model/timing/pipeline.h"
#include "hw_model/timing/tokens.h"
#include "hw_model/timing/unit.h"

namespace qacc {

class HierarchicalZUnit;

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
  bool tick(std::uint64_t now) override;
  std::uint64_t nextEvent() const override;
  bool holdsWork() const override;
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
  Params p_;
  const HwConfig& cfg_;  // the stored Z format (ZBufferMemory::storedValue)
  ZBufferMemory& zb_;
  std::vector<Channel<PointToken>*> in_, out_;
  PixelCounters& px_;
  int bankOf(int x, int y) const { return ZBufferMemory::bankOf(x, y, p_.banks); }
  std::vector<std::uint64_t> bankFree_;
  std::vector<Pipeline<InFlight>> reads_;  // per pipeline port
  std::uint64_t conflicts_ = 0;
  std::size_t rr_ = 0;
  bool sceneOrderTies_ = false;
  HierarchicalZUnit* hiz_ = nullptr;
};

}  // namespace qacc
