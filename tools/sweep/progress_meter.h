// ProgressMeter: "points done / total, elapsed, time left" on one rewritten line of stderr
// when stderr is a terminal; silent otherwise (logs, pipes, GNU parallel, Slurm).
#pragma once
#include <chrono>
#include <cstddef>
#include <string>

namespace qacc {

class ProgressMeter {
 public:
  ProgressMeter(std::size_t total, std::string what);
  void step(const std::string& label);  // one more done
  void finish();
  bool active() const { return active_; }

 private:
  std::size_t total_, done_ = 0;
  std::string what_;
  bool active_;
  std::chrono::steady_clock::time_point t0_;
};

}  // namespace qacc
