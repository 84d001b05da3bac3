#include "hw_model/timing/zbuffer_unit.h"

#include <algorithm>

namespace qacc {

ZBufferUnit::ZBufferUnit(const Params& p, const HwConfig& cfg, ChannelRegistry& wires, ZBufferMemory& zb,
                         std::vector<Channel<PointToken>*> in, std::vector<Channel<PointToken>*> out,
                         PixelCounters& px)
    : Unit("zbuffer"), p_(p), cfg_(cfg), zb_(zb), in_(std::move(in)), out_(std::move(out)), px_(px),
      bankFree_(std::size_t(p.banks), 0) {
  reads_.reserve(in_.size());
  for (std::size_t i = 0; i < in_.size(); ++i) reads_.emplace_back(wires, std::uint64_t(p.read_latency));
}

std::uint64_t ZBufferUnit::nextEvent() const {
  std::uint64_t t = kNoEvent;
  for (std::size_t p = 0; p < in_.size(); ++p) {
    t = std::min(t, reads_[p].nextEvent(false));
    if (in_[p]->ready()) {
      const PointToken& r = in_[p]->front();
      t = std::min(t, bankFree_[std::size_t(bankOf(r.x, r.y))]);
    }
  }
  return t;
}

}  // namespace qacc
