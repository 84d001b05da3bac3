#include "tools/sweep/progress_meter.h"

#include <cstdio>

#include <unistd.h>

namespace qacc {

ProgressMeter::ProgressMeter(std::size_t total, std::string what)
    : total_(total), what_(std::move(what)), active_(::isatty(2) != 0), t0_(std::chrono::steady_clock::now()) {}

void ProgressMeter::step(const std::string& label) {
  ++done_;
  if (!active_) return;
  const double el = std::chrono::duration<double>(std::chrono::steady_clock::now() - t0_).count();
  const double left = done_ ? el / double(done_) * double(total_ - done_) : 0;
  std::fprintf(stderr, "\r\033[K%s %zu/%zu, %.0f s elapsed, %.0f s left  %.60s", what_.c_str(), done_, total_, el, left,
               label.c_str());
  std::fflush(stderr);
}

void ProgressMeter::finish() {
  if (active_) std::fprintf(stderr, "\r\033[K");
}

}  // namespace qacc
