// Fifo<T>: a bounded FIFO between two units, updated in two phases so that the order in
// which units tick within a cycle does not matter: a push made during cycle t becomes
// visible to the consumer at t + 1, and a slot freed by a pop during cycle t can be
// refilled at t + 1 (commit() ends the cycle).
// Storage is a ring of `capacity` slots: pops free slots at once, but canPush() counts the
// occupancy at the start of the cycle, so visible + staged entries never exceed it.
#pragma once
#include <cstddef>
#include <vector>

namespace qacc {

template <typename T>
class Fifo {
 public:
  explicit Fifo(std::size_t capacity = 1) : capacity_(capacity), ring_(capacity) {}
  // Producer side: room for one more this cycle?
  bool canPush() const { return visibleAtStart_ + staged_ < capacity_; }
  void push(const T& v) {
    std::size_t slot = head_ + visible_ + staged_;
    if (slot >= capacity_) slot -= capacity_;
    ring_[slot] = v;
    ++staged_;
  }
  // Consumer side: sees only what was committed before this cycle.
  bool empty() const { return visible_ == 0; }
  const T& front() const { return ring_[head_]; }
  void pop() {
    if (++head_ == capacity_) head_ = 0;
    --visible_;
    ++popped_;
  }
  // End of cycle: staged pushes become visible, pops free their slots.
  bool commit() {
    const bool changed = staged_ > 0 || popped_ > 0;
    visible_ += staged_;
    staged_ = 0;
    popped_ = 0;
    visibleAtStart_ = visible_;
    return changed;
  }
  std::size_t size() const { return visible_; }
  bool idle() const { return visible_ == 0 && staged_ == 0; }
  std::size_t capacity() const { return capacity_; }

 private:
  std::size_t capacity_;
  std::vector<T> ring_;
  std::size_t head_ = 0, visible_ = 0, staged_ = 0, popped_ = 0, visibleAtStart_ = 0;
};

}  // namespace qacc
