// ZBufferUnit: read-compare-write of the depth of each covered pixel against a banked
// memory model. Pixel (x, y) lives in bank (x + y) mod zbuffer_banks; a read-modify-write
// occupies its bank for zbuffer_bank_busy cycles, so a request to a busy bank waits (a
// bank conflict, counted as a stall); the result is known zbuffer_read_latency cycles
// after issue. The comparison keeps the earlier primitive on equal depths (strict <).
// Up to one request per pipeline per cycle; each pipeline's requests stay in order, and
// a pixel always goes through the same pipeline, so the Z test sees every pixel's
// primitives in scene order. Pixels that pass go to that pipeline's shading unit.
#pragma once
#include <vector>

#include "hw_model/timing/delay_queue.h"
#include "hw_model/timing/fifo.h"
#include "hw_model/config/hw_config.h"
#include "hw_model/engines/frame_setup.h"
#include "hw_model/timing/pixel_pipeline_unit.h"
#include "hw_model/timing/shading_unit.h"
#include "hw_model/timing/unit.h"

namespace qacc {

class ZBufferUnit : public Unit {
 public:
  // The functional test: true (and the buffer updated) when z is nearer than the stored depth.
  static bool testAndWrite(ZBufferState& zb, std::size_t pix, std::uint32_t z, int prim, i128 depth, int cap) {
    ZEntry& e = zb.px[pix];
    if (!(z < e.z)) return false;
    e = {std::int64_t(depth), z, prim, std::int16_t(cap)};
    return true;
  }
  static int bankOf(int x, int y, int banks) { return (x + y) % banks; }

  ZBufferUnit(const HwConfig& cfg, ZBufferState& zb, std::vector<Fifo<ZRequest>>& in,
              std::vector<Fifo<ShadeRequest>>& out, PixelCounters& px)
      : Unit("zbuffer"), cfg_(cfg), zb_(zb), in_(in), out_(out), px_(px), bankFree_(std::size_t(cfg.zbuffer_banks), 0),
        inflight_(in.size()) {}
  bool tick(std::uint64_t now) override;
  std::uint64_t nextEvent() const override;
  bool holdsWork() const override;
  std::uint64_t conflicts() const { return conflicts_; }

 private:
  struct InFlight {
    std::uint64_t ready;
    bool pass;
    ShadeRequest req;
  };
  const HwConfig& cfg_;
  ZBufferState& zb_;
  std::vector<Fifo<ZRequest>>& in_;
  std::vector<Fifo<ShadeRequest>>& out_;
  PixelCounters& px_;
  std::vector<std::uint64_t> bankFree_;
  std::vector<DelayQueue<InFlight>> inflight_;
  std::uint64_t conflicts_ = 0;
  std::size_t rr_ = 0;
};

}  // namespace qacc
