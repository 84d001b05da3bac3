// Channel<T>: a wire between timed units that carries a latency (design §3.2): an item
// sent during cycle t with delay d (d >= 1) can be taken by the receiver from cycle t + d
// on, and items leave in the order they were sent. A channel has a capacity (0: none; a
// unit's own stages are a Pipeline, pipeline.h) counted at the start of the cycle: a slot freed
// by a receive during cycle t can be refilled from t + 1, so the order in which units
// tick within a cycle does not matter. Channels are made by a ChannelRegistry
// (channel_registry.h), which holds the current cycle. A channel keeps its two-phase state
// itself: it counts the receives of the current cycle (its first receive of a cycle starts
// the count), so the occupancy at the start of the cycle is what it holds plus what left it
// during the cycle, and it tells the registry that something moved, so no per-cycle commit
// pass over the channels is needed. The oldest item's arrival is kept beside the queue, so
// the receiver's poll (`ready`) is one comparison.
#pragma once
#include <cassert>
#include <cstddef>
#include <cstdint>
#include <limits>
#include <vector>

#include "hw_model/timing/delay_queue.h"

namespace qacc {

// What the registry needs of every channel.
class ChannelBase {
 public:
  virtual ~ChannelBase() = default;
  // Nothing sent and not yet received.
  virtual bool idle() const = 0;
};

template <typename T>
class Channel : public ChannelBase {
 public:
  static constexpr std::uint64_t kNever = std::numeric_limits<std::uint64_t>::max();

  // `moves`: the registry's count of sends and receives in the current cycle.
  Channel(const std::uint64_t& now, std::size_t capacity, std::uint64_t& moves)
      : now_(now), capacity_(capacity), limit_(capacity == 0 ? std::numeric_limits<std::size_t>::max() : capacity),
        moves_(moves) {}
  // Sender: room for one more this cycle? (The occupancy at the start of the cycle plus what
  // was sent during it, i.e. what it holds now plus what was received during the cycle: a
  // receive frees its slot from the next cycle.)
  bool canSend() const { return q_.size() + (receivedIn_ == now_ ? received_ : 0) < limit_; }
  void send(const T& v, std::uint64_t delay = 1) {
    assert(delay >= 1 && canSend());
    const std::uint64_t arrival = now_ + delay;
    assert(q_.empty() || q_.back().arrival <= arrival);  // items leave in order
    if (q_.empty()) head_ = arrival;
    q_.push_back({arrival, v});
    ++moves_;
  }
  // Receiver: the oldest item, once it has arrived.
  bool ready() const { return head_ <= now_; }
  const T& front() const { return q_.front().item; }
  void receive() {
    assert(ready());
    if (receivedIn_ != now_) {
      receivedIn_ = now_;
      received_ = 0;
    }
    ++received_;
    q_.pop_front();
    head_ = q_.empty() ? kNever : q_.front().arrival;
    ++moves_;
  }
  // Cycle at which the oldest item arrives (kNever when the channel is empty).
  std::uint64_t nextArrival() const { return head_; }
  // The oldest item's arrival if it is still to come at `now` (kNever: arrived, or empty).
  std::uint64_t arrivalFrom(std::uint64_t now) const { return head_ >= now ? head_ : kNever; }
  bool empty() const { return q_.empty(); }
  std::size_t size() const { return q_.size(); }
  std::size_t capacity() const { return capacity_; }

  bool idle() const override { return q_.empty(); }

 private:
  struct Entry {
    std::uint64_t arrival;
    T item;
  };
  const std::uint64_t& now_;
  std::size_t capacity_;
  std::size_t limit_;  // the capacity, or the largest size_t for an unbounded channel
  std::uint64_t& moves_;
  DelayQueue<Entry> q_;
  std::uint64_t head_ = kNever;        // the oldest item's arrival (kNever: empty)
  std::uint64_t receivedIn_ = kNever;  // the cycle received_ counts the receives of
  std::size_t received_ = 0;
};

}  // namespace qacc
