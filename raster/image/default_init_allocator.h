// DefaultInitAllocator<T>: the allocator of frame-sized buffers. Its value-less construct()
// default-initialises, so std::vector<T, DefaultInitAllocator<T>>(n) of a trivial T leaves
// the memory untouched (no frame-sized memset before a renderer overwrites every element
// anyway, and the pages are first touched by the threads that fill them). Construction
// with a value, resize with a value, assign and push_back behave as with std::allocator.
// Blocks of 2 MiB and more ask for transparent huge pages: first touching 40 MB (a
// 1920x1080 frame buffer) took 25 ms in 4 KiB pages and 5 ms in 2 MiB pages on the
// project's machine (docs/PERFORMANCE.md).
#pragma once
#include <sys/mman.h>

#include <cstdlib>
#include <memory>
#include <new>
#include <utility>

namespace qacc {

template <typename T>
class DefaultInitAllocator : public std::allocator<T> {
 public:
  template <typename U>
  struct rebind {
    using other = DefaultInitAllocator<U>;
  };
  using std::allocator<T>::allocator;
  // Frame-sized blocks (2 MiB and more) are aligned to 2 MiB and offered to the kernel's
  // transparent huge pages (madvise): their first touch then faults once per 2 MiB
  // instead of once per 4 KiB page. Smaller blocks come from std::allocator.
  static constexpr std::size_t kHugePage = std::size_t(2) << 20;
  T* allocate(std::size_t n) {
    const std::size_t bytes = n * sizeof(T);
    if (n > std::size_t(-1) / sizeof(T) || bytes < kHugePage) return std::allocator<T>::allocate(n);
    const std::size_t rounded = (bytes + kHugePage - 1) / kHugePage * kHugePage;
    void* p = std::aligned_alloc(kHugePage, rounded);
    if (!p) throw std::bad_alloc();
    madvise(p, rounded, MADV_HUGEPAGE);  // advice only: without huge pages the block is as before
    return static_cast<T*>(p);
  }
  void deallocate(T* p, std::size_t n) {
    if (n * sizeof(T) < kHugePage) return std::allocator<T>::deallocate(p, n);
    std::free(p);
  }
  template <typename U>
  void construct(U* p) noexcept(std::is_nothrow_default_constructible_v<U>) {
    ::new (static_cast<void*>(p)) U;
  }
  template <typename U, typename... Args>
  void construct(U* p, Args&&... args) {
    ::new (static_cast<void*>(p)) U(std::forward<Args>(args)...);
  }
};

// A vector whose size-only construction and resize leave trivial elements uninitialised.
template <typename T>
using UninitVector = std::vector<T, DefaultInitAllocator<T>>;

}  // namespace qacc
