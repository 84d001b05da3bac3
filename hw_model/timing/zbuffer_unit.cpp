#include "hw_model/timing/zbuffer_unit.h"

#include <algorithm>

namespace qacc {

ZBufferUnit::ZBufferUnit(const Params& p, const HwConfig& cfg, ChannelRegistry& wires, ZBufferMemory& zb,
                         std::vector<Channel<PointToken>*> in, std::vector<Channel<PointToken>*> out,
                         PixelCounters& px)
    : Unit("zbuffer"), p_(p), stored_(ZBufferMemory::StoredFormat::from(cfg)), zb_(zb), px_(px),
      bankFree_(std::size_t(p.banks), 0) {
  ports_.reserve(in.size());
  for (std::size_t i = 0; i < in.size(); ++i)
    ports_.push_back({in[i], out[i], Pipeline<InFlight>(wires, std::uint64_t(p.read_latency))});
}

std::uint64_t ZBufferUnit::nextEvent() const {
  std::uint64_t t = kNoEvent;
  for (const Port& port : ports_) {
    t = std::min(t, port.reads.nextEvent(false));
    if (port.in->ready()) {
      const PointToken& r = port.in->front();
      t = std::min(t, bankFree_[std::size_t(bankOf(r.x, r.y))]);
    }
  }
  return t;
}

std::uint64_t ZBufferUnit::nextChange(std::uint64_t now) const {
  std::uint64_t t = kNoEvent;
  for (const Port& port : ports_) {
    t = std::min(t, port.reads.nextChange(now, Channel<PointToken>::kNever));
    const std::uint64_t arrival = port.in->nextArrival();
    if (arrival == Channel<PointToken>::kNever) continue;
    if (arrival >= now) {
      t = std::min(t, arrival);
    } else {  // arrived: waiting for its bank
      const PointToken& r = port.in->front();
      t = std::min(t, std::max(now, bankFree_[std::size_t(bankOf(r.x, r.y))]));
    }
  }
  return t;
}

}  // namespace qacc
