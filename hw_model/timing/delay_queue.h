// DelayQueue<T>: the storage of a channel (channel.h) — a FIFO ring buffer that grows by
// doubling (a channel's capacity, or a pipeline's depth, bounds it after the first few
// cycles), so the cycle loop allocates nothing in steady state. The ring's index mask is
// kept beside its pointer: a push or a pop is a store or a load, an add and an AND.
#pragma once
#include <cassert>
#include <cstddef>
#include <memory>
#include <utility>

namespace qacc {

template <typename T>
class DelayQueue {
 public:
  DelayQueue() : ring_(new T[kInitial]), mask_(kInitial - 1) {}
  DelayQueue(const DelayQueue&) = delete;
  DelayQueue& operator=(const DelayQueue&) = delete;
  // Moving takes the ring; the queue moved from is empty and has no ring: it may only be
  // destroyed or assigned to.
  DelayQueue(DelayQueue&& o) noexcept : ring_(std::move(o.ring_)), mask_(o.mask_), head_(o.head_), size_(o.size_) {
    o.head_ = o.size_ = 0;
  }
  DelayQueue& operator=(DelayQueue&& o) noexcept {
    ring_ = std::move(o.ring_);
    mask_ = o.mask_;
    head_ = o.head_;
    size_ = o.size_;
    o.head_ = o.size_ = 0;
    return *this;
  }
  bool empty() const { return size_ == 0; }
  std::size_t size() const { return size_; }
  T& front() { return ring_[head_]; }
  const T& front() const { return ring_[head_]; }
  const T& back() const { return ring_[(head_ + size_ - 1) & mask_]; }
  void push_back(const T& v) {
    assert(ring_);
    if (size_ > mask_) grow();
    ring_[(head_ + size_) & mask_] = v;
    ++size_;
  }
  void pop_front() {
    head_ = (head_ + 1) & mask_;
    --size_;
  }

 private:
  static constexpr std::size_t kInitial = 16;  // a power of two
  void grow() {
    const std::size_t n = 2 * (mask_ + 1);
    std::unique_ptr<T[]> bigger(new T[n]);
    for (std::size_t i = 0; i < size_; ++i) bigger[i] = ring_[(head_ + i) & mask_];
    ring_ = std::move(bigger);
    mask_ = n - 1;
    head_ = 0;
  }
  std::unique_ptr<T[]> ring_;
  std::size_t mask_;  // capacity - 1
  std::size_t head_ = 0, size_ = 0;
};

}  // namespace qacc
