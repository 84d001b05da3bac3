// DelayQueue<T>: the storage of a channel (channel.h) — a FIFO ring buffer that grows by
// doubling (a channel's capacity, or a pipeline's depth, bounds it after the first few
// cycles), so the cycle loop allocates nothing in steady state.
#pragma once
#include <cstddef>
#include <vector>

namespace qacc {

template <typename T>
class DelayQueue {
 public:
  bool empty() const { return size_ == 0; }
  std::size_t size() const { return size_; }
  T& front() { return ring_[head_]; }
  const T& front() const { return ring_[head_]; }
  const T& back() const { return ring_[(head_ + size_ - 1) & (ring_.size() - 1)]; }
  void push_back(const T& v) {
    if (size_ == ring_.size()) grow();
    ring_[(head_ + size_) & (ring_.size() - 1)] = v;
    ++size_;
  }
  void pop_front() {
    head_ = (head_ + 1) & (ring_.size() - 1);
    --size_;
  }

 private:
  void grow() {
    std::vector<T> bigger(ring_.empty() ? 16 : 2 * ring_.size());
    for (std::size_t i = 0; i < size_; ++i) bigger[i] = ring_[(head_ + i) & (ring_.size() - 1)];
    ring_.swap(bigger);
    head_ = 0;
  }
  std::vector<T> ring_;
  std::size_t head_ = 0, size_ = 0;
};

}  // namespace qacc
