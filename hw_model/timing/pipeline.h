// Pipeline<T>: the in-order stages of a pipelined unit — it accepts an item at most once
// every `interval` cycles (the initiation interval, per item), and each item leaves
// `latency` cycles after it entered, in order. The stages belong to the unit: it reports
// an accept or a retire as a change of its tick and the items in flight as its work
// (Unit::holdsWork), so they are not a wire of the registry, only timed by its clock. The
// unit decides what happens when a finished item cannot leave (it stays, and the stages
// behind it wait).
#pragma once
#include <algorithm>
#include <cassert>
#include <cstdint>
#include <limits>

#include "hw_model/timing/channel_registry.h"
#include "hw_model/timing/delay_queue.h"

namespace qacc {

template <typename T>
class Pipeline {
 public:
  static constexpr std::uint64_t kNever = std::numeric_limits<std::uint64_t>::max();
  Pipeline(const ChannelRegistry& registry, std::uint64_t latency) : now_(registry.clock()), latency_(latency) {
    assert(latency >= 1);  // an item leaves in a later cycle than it entered
  }
  std::uint64_t latency() const { return latency_; }
  // Input side.
  bool canAccept() const { return now_ >= nextAccept_; }
  void accept(const T& item, std::uint64_t interval = 1) {
    const std::uint64_t finish = now_ + latency_;
    if (stages_.empty()) head_ = finish;
    stages_.push_back({finish, item});
    nextAccept_ = now_ + interval;
  }
  // Output side: the oldest item, once its latency has passed.
  bool done() const { return head_ <= now_; }
  const T& front() const { return stages_.front().item; }
  void retire() {
    stages_.pop_front();
    head_ = stages_.empty() ? kNever : stages_.front().finish;
  }
  bool holdsWork() const { return !stages_.empty(); }
  // The next cycle at which the pipeline acts by itself: its oldest item finishing or,
  // when input waits, its next accept.
  std::uint64_t nextEvent(bool inputWaiting) const {
    return inputWaiting ? std::min(head_, nextAccept_) : head_;
  }
  // For a unit whose tick before `now` changed nothing (Unit::nextChange): the first cycle
  // from `now` on at which the oldest item finishes, or at which an input that has arrived by
  // then (`inputArrival`, kNever: none) can be accepted.
  std::uint64_t nextChange(std::uint64_t now, std::uint64_t inputArrival) const {
    std::uint64_t t = head_ >= now ? head_ : kNever;
    if (inputArrival != kNever) t = std::min(t, std::max({now, nextAccept_, inputArrival}));
    return t;
  }

 private:
  struct Stage {
    std::uint64_t finish;  // the cycle from which the item can leave
    T item;
  };
  const std::uint64_t& now_;
  std::uint64_t latency_;
  std::uint64_t nextAccept_ = 0;
  DelayQueue<Stage> stages_;
  std::uint64_t head_ = kNever;  // the oldest item's finish (kNever: empty)
};

}  // namespace qacc
