// DefaultInitAllocator<T>: std::allocator whose value-less construct() default-initialises,
// so std::vector<T, DefaultInitAllocator<T>>(n) of a trivial T leaves the memory untouched
// (no frame-sized memset before a renderer overwrites every element anyway, and the pages
// are first touched by the threads that fill them). Construction with a value, resize
// with a value, assign and push_back behave as with std::allocator.
#pragma once
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
