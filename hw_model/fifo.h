// Fifo<T>: a bounded FIFO between two units, updated in two phases so that the order in
// which units tick within a cycle does not matter: a push made during cycle t becomes
// visible to the consumer at t + 1, and a slot freed by a pop during cycle t can be
// refilled at t + 1 (commit() ends the cycle).
#pragma once
#include <cstddef>
#include <deque>
#include <vector>

namespace qacc {

template <typename T>
class Fifo {
 public:
  explicit Fifo(std::size_t capacity = 1) : capacity_(capacity) {}
  // Producer side: room for one more this cycle?
  bool canPush() const { return visibleAtStart_ + staged_.size() < capacity_; }
  void push(const T& v) { staged_.push_back(v); }
  // Consumer side: sees only what was committed before this cycle.
  bool empty() const { return visible_.empty(); }
  const T& front() const { return visible_.front(); }
  void pop() {
    visible_.pop_front();
    ++popped_;
  }
  // End of cycle: staged pushes become visible, pops free their slots.
  bool commit() {
    const bool changed = !staged_.empty() || popped_ > 0;
    for (auto& v : staged_) visible_.push_back(std::move(v));
    staged_.clear();
    popped_ = 0;
    visibleAtStart_ = visible_.size();
    return changed;
  }
  std::size_t size() const { return visible_.size(); }
  bool idle() const { return visible_.empty() && staged_.empty(); }
  std::size_t capacity() const { return capacity_; }

 private:
  std::size_t capacity_;
  std::deque<T> visible_;
  std::vector<T> staged_;
  std::size_t popped_ = 0;
  std::size_t visibleAtStart_ = 0;
};

}  // namespace qacc
