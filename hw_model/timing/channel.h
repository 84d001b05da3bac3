// Channel<T>: a wire between timed units that carries a latency (design §3.2): an item
// sent during cycle t with delay d (d >= 1) can be taken by the receiver from cycle t + d
// on, and items leave in the order they were sent. A channel has a capacity (0: none,
// for the stages inside a pipelined unit) counted at the start of the cycle: a slot freed
// by a receive during cycle t can be refilled from t + 1, so the order in which units
// tick within a cycle does not matter. Channels are made by a ChannelRegistry
// (channel_registry.h), which holds the current cycle and commits every channel at the
// end of it.
#pragma once
#include <cassert>
#include <cstddef>
#include <cstdint>
#include <limits>

#include "hw_model/timing/delay_queue.h"

namespace qacc {

// What the registry needs of every channel.
class ChannelBase {
 public:
  virtual ~ChannelBase() = default;
  // End of cycle; true when anything was sent or received during it.
  virtual bool commit() = 0;
  // Nothing sent and not yet received.
  virtual bool idle() const = 0;
};

template <typename T>
class Channel : public ChannelBase {
 public:
  static constexpr std::uint64_t kNever = std::numeric_limits<std::uint64_t>::max();

  Channel(const std::uint64_t& now, std::size_t capacity) : now_(now), capacity_(capacity) {}
  // Sender: room for one more this cycle?
  bool canSend() const { return capacity_ == 0 || atStart_ + sent_ < capacity_; }
  void send(const T& v, std::uint64_t delay = 1) {
    assert(delay >= 1 && canSend());
    const std::uint64_t arrival = now_ + delay;
    assert(q_.empty() || q_.back().arrival <= arrival);  // items leave in order
    q_.push_back({arrival, v});
    ++sent_;
  }
  // Receiver: the oldest item, once it has arrived.
  bool ready() const { return !q_.empty() && q_.front().arrival <= now_; }
  const T& front() const { return q_.front().item; }
  void receive() {
    assert(ready());
    q_.pop_front();
    ++received_;
  }
  // Cycle at which the oldest item arrives (kNever when the channel is empty).
  std::uint64_t nextArrival() const { return q_.empty() ? kNever : q_.front().arrival; }
  bool empty() const { return q_.empty(); }
  std::size_t size() const { return q_.size(); }
  std::size_t capacity() const { return capacity_; }

  bool commit() override {
    const bool changed = sent_ > 0 || received_ > 0;
    sent_ = received_ = 0;
    atStart_ = q_.size();
    return changed;
  }
  bool idle() const override { return q_.empty(); }

 private:
  struct Entry {
    std::uint64_t arrival;
    T item;
  };
  const std::uint64_t& now_;
  std::size_t capacity_;
  DelayQueue<Entry> q_;
  std::size_t atStart_ = 0, sent_ = 0, received_ = 0;
};

}  // namespace qacc
