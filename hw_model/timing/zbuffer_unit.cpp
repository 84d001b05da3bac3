#include "hw_model/timing/zbuffer_unit.h"

#include <algorithm>

#include "hw_model/timing/hierarchical_z_unit.h"

namespace qacc {

ZBufferUnit::ZBufferUnit(const Params& p, const HwConfig& cfg, ChannelRegistry& wires, ZBufferMemory& zb,
                         std::vector<Channel<PointToken>*> in, std::vector<Channel<PointToken>*> out,
                         PixelCounters& px)
    : Unit("zbuffer"), p_(p), cfg_(cfg), zb_(zb), in_(std::move(in)), out_(std::move(out)), px_(px),
      bankFree_(std::size_t(p.banks), 0) {
  reads_.reserve(in_.size());
  for (std::size_t i = 0; i < in_.size(); ++i) reads_.emplace_back(wires, std::uint64_t(p.read_latency));
}

bool ZBufferUnit::tick(std::uint64_t now) {
  bool changed = false, stalled = false;
  const std::size_t P = in_.size();
  for (std::size_t p = 0; p < P; ++p) {
    Pipeline<InFlight>& q = reads_[p];
    while (q.done()) {
      if (q.front().pass) {
        if (!out_[p]->canSend()) {
          stalled = true;
          break;
        }
        out_[p]->send(q.front().point);
      }
      q.retire();
      changed = true;
    }
  }
  // Issue: one request per pipeline, round-robin priority on bank conflicts.
  for (std::size_t k = 0; k < P; ++k) {
    const std::size_t p = rr_ + k < P ? rr_ + k : rr_ + k - P;
    Channel<PointToken>& in = *in_[p];
    if (!in.ready()) continue;
    const PointToken& r = in.front();
    const int bank = bankOf(r.x, r.y);
    if (bankFree_[std::size_t(bank)] > now) {
      ++conflicts_;
      stalled = true;
      continue;
    }
    bankFree_[std::size_t(bank)] = now + std::uint64_t(p_.bank_busy);
    const std::size_t pix = zb_.index(r.x, r.y);
    const std::uint32_t stored = ZBufferMemory::storedValue(r.z, cfg_);
    const bool pass = sceneOrderTies_ ? zb_.testAndWriteInSceneOrder(pix, stored, r.prim, r.z, r.cap)
                                      : zb_.testAndWrite(pix, stored, r.prim, r.z, r.cap);
    if (pass && hiz_) hiz_->noteWrite(now, r.x, r.y, stored);
    if (pass) ++px_.written;
    else ++px_.depth_rejected;
    reads_[p].accept({pass, r});
    in.receive();
    countItem();
    changed = true;
  }
  if (++rr_ == P) rr_ = 0;
  countCycle(changed, stalled, holdsWork());
  return changed;
}

std::uint64_t ZBufferUnit::nextEvent() const {
  std::uint64_t t = Unit::nextEvent();
  for (std::size_t p = 0; p < in_.size(); ++p) {
    t = std::min(t, reads_[p].nextEvent(false));
    if (in_[p]->ready()) {
      const PointToken& r = in_[p]->front();
      t = std::min(t, bankFree_[std::size_t(bankOf(r.x, r.y))]);
    }
  }
  return t;
}

bool ZBufferUnit::holdsWork() const {
  for (const auto& q : reads_)
    if (q.holdsWork()) return true;
  return false;
}

}  // namespace qacc
