// ParallelErrors: exceptions out of OpenMP loops. An exception that leaves the body of an
// OpenMP parallel region terminates the process ("terminate called recursively"), so every
// parallel loop whose body can throw (builders, renderers) runs it through run(), which keeps
// the first exception; after the loop, rethrow() throws it on the calling thread, where the
// scene loader turns it into "FILE: /json/path: problem". Iterations after the first failure
// are skipped.
#pragma once
#include <atomic>
#include <exception>
#include <mutex>

namespace qacc {

class ParallelErrors {
 public:
  template <class Body>
  void run(Body&& body) noexcept {
    if (failed_.load(std::memory_order_relaxed)) return;
    try {
      body();
    } catch (...) {
      std::lock_guard<std::mutex> lock(mutex_);
      if (!first_) first_ = std::current_exception();
      failed_.store(true, std::memory_order_relaxed);
    }
  }
  void rethrow() const {
    if (first_) std::rethrow_exception(first_);
  }

 private:
  std::atomic<bool> failed_{false};
  std::mutex mutex_;
  std::exception_ptr first_;
};

}  // namespace qacc
