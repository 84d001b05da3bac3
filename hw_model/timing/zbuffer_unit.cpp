#include "hw_model/timing/zbuffer_unit.h"

#include <algorithm>

#include "hw_model/datapath/depth_roots.h"

namespace qacc {

bool ZBufferUnit::tick(std::uint64_t now) {
  bool changed = false, stalled = false;
  const std::size_t P = in_.size();
  for (std::size_t p = 0; p < P; ++p) {
    auto& q = inflight_[p];
    while (!q.empty() && q.front().ready <= now) {
      if (q.front().pass) {
        if (!out_[p].canPush()) {
          stalled = true;
          break;
        }
        out_[p].push(q.front().req);
      }
      q.pop_front();
      changed = true;
    }
  }
  // Issue: one request per pipeline, round-robin priority on bank conflicts.
  for (std::size_t k = 0; k < P; ++k) {
    const std::size_t p = (rr_ + k) % P;
    if (in_[p].empty()) continue;
    const ZRequest& r = in_[p].front();
    const int bank = bankOf(r.x, r.y, cfg_.zbuffer_banks);
    if (bankFree_[std::size_t(bank)] > now) {
      ++conflicts_;
      stalled = true;
      continue;
    }
    bankFree_[std::size_t(bank)] = now + std::uint64_t(cfg_.zbuffer_bank_busy);
    const std::size_t pix = std::size_t(r.y) * std::size_t(zb_.width) + std::size_t(r.x);
    const bool pass = testAndWrite(zb_, pix, DepthUnit::zbufferValue(r.z, cfg_), r.prim, r.z, r.cap);
    if (pass) ++px_.written;
    else ++px_.depth_rejected;
    inflight_[p].push_back({now + std::uint64_t(cfg_.zbuffer_read_latency), pass, {r.prim, r.x, r.y, r.cap, r.z}});
    in_[p].pop();
    countItem();
    changed = true;
  }
  rr_ = (rr_ + 1) % P;
  if (stalled && !changed) countStall();
  else if (changed || holdsWork()) countBusy();
  else countIdle();
  return changed;
}

std::uint64_t ZBufferUnit::nextEvent() const {
  std::uint64_t t = Unit::nextEvent();
  for (std::size_t p = 0; p < in_.size(); ++p) {
    if (!inflight_[p].empty()) t = std::min(t, inflight_[p].front().ready);
    if (!in_[p].empty()) {
      const ZRequest& r = in_[p].front();
      t = std::min(t, bankFree_[std::size_t(bankOf(r.x, r.y, cfg_.zbuffer_banks))]);
    }
  }
  return t;
}

bool ZBufferUnit::holdsWork() const {
  for (const auto& q : inflight_)
    if (!q.empty()) return true;
  return false;
}

}  // namespace qacc
