// Pipeline<T>: the in-order stages of a pipelined unit — it accepts an item at most once
// every `interval` cycles (the initiation interval, per item), and each item leaves
// `latency` cycles after it entered, in order. The stages are an unbounded channel of the
// registry (an item in flight occupies a stage, not a FIFO slot); the unit decides what
// happens when a finished item cannot leave (it stays, and the stages behind it wait).
#pragma once
#include <algorithm>
#include <cstdint>

#include "hw_model/timing/channel_registry.h"

namespace qacc {

template <typename T>
class Pipeline {
 public:
  Pipeline(ChannelRegistry& registry, std::uint64_t latency)
      : registry_(registry), stages_(registry.make<T>(0)), latency_(latency) {}
  std::uint64_t latency() const { return latency_; }
  // Input side.
  bool canAccept() const { return registry_.now() >= nextAccept_; }
  void accept(const T& item, std::uint64_t interval = 1) {
    stages_.send(item, latency_);
    nextAccept_ = registry_.now() + interval;
  }
  // Output side: the oldest item, once its latency has passed.
  bool done() const { return stages_.ready(); }
  const T& front() const { return stages_.front(); }
  void retire() { stages_.receive(); }
  bool holdsWork() const { return !stages_.empty(); }
  // The next cycle at which the pipeline acts by itself: its oldest item finishing or,
  // when input waits, its next accept.
  std::uint64_t nextEvent(bool inputWaiting) const {
    std::uint64_t t = stages_.nextArrival();
    if (inputWaiting) t = std::min(t, nextAccept_);
    return t;
  }

 private:
  ChannelRegistry& registry_;
  Channel<T>& stages_;
  std::uint64_t latency_;
  std::uint64_t nextAccept_ = 0;
};

}  // namespace qacc
